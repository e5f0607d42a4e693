#include <simp/maps/CObjectMap.h>
#include <simp/maps/CObjectMapCreationOptions.h>
#include <simp/obs/ObjectClasses.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

// "semanticObjectMap" is the short name used in .ini files: semanticObjectMap_count=1.
MAP_DEFINITION_REGISTER("simp::maps::CObjectMap,semanticObjectMap", simp::maps::CObjectMap)

namespace simp::maps {
namespace {

std::vector<std::string> splitClassList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const auto b = item.find_first_not_of(" \t\"");
        if (b == std::string::npos) continue;
        const auto e = item.find_last_not_of(" \t\"");
        out.push_back(item.substr(b, e - b + 1));
    }
    return out;
}

}  // namespace

// ---------------------------------------------------------------- map definition (.ini)
const io::OptionTable<CObjectMap::TMapDefinition>& creationOptionsTable() {
    using O = CObjectMap::TMapDefinition;
    const auto text = [](std::string O::*field) {
        return std::make_pair([field](O& o, const std::string& t, const std::string&) { o.*field = t; },
                              [field](const O& o, int) { return o.*field; });
    };
    static const io::OptionTable<O> t = [&] {
        io::OptionTable<O> t("_creationOpts");
        const auto [load_file, print_file] = text(&O::map_file);
        const auto [load_classes, print_classes] = text(&O::class_names);
        t.custom("map_file", "", "a path", "object map JSON (`doc/formats.md`), relative to the working directory; empty = an empty map",
                 load_file, print_file)
            .custom("class_names", "", "a comma-separated list",
                    "when set, objects of other classes are dropped and class ids / class noise follow the names. With no "
                    "`map_file` it is the class list of the empty map (default: the detector's 14 classes)",
                    load_classes, print_classes);
        return t;
    }();
    return t;
}

CObjectMap::TMapDefinition::TMapDefinition() = default;

void CObjectMap::TMapDefinition::loadFromConfigFile_map_specific(const mrpt::config::CConfigFileBase& source,
                                                                 const std::string& sectionNamePrefix) {
    // Never throws: see load_error (the leak LeakSanitizer found in MRPT's loader).
    load_error.clear();
    try {
        const std::string creation = sectionNamePrefix + "_creationOpts";
        creationOptionsTable().load(source, creation, *this);
        likelihoodOpts.loadFromConfigFile(source, sectionNamePrefix + "_likelihoodOpts");
        insertionOpts.loadFromConfigFile(source, sectionNamePrefix + "_insertOpts");
    } catch (const std::exception& e) {
        load_error = e.what();
        if (load_error.empty()) load_error = "semanticObjectMap: invalid options in [" + sectionNamePrefix + "_*]";
    }
}

void CObjectMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const {
    if (!load_error.empty()) out << "load error                              = " << load_error << "\n";
    creationOptionsTable().dump(*this, out);
    likelihoodOpts.dumpToTextStream(out);
    insertionOpts.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CObjectMap::internal_CreateFromMapDefinition(const mrpt::maps::TMetricMapInitializer& _def) {
    const auto& def = dynamic_cast<const CObjectMap::TMapDefinition&>(_def);
    if (!def.load_error.empty()) throw std::invalid_argument(def.load_error);
    auto obj = std::make_unique<CObjectMap>();
    obj->likelihoodOptions = def.likelihoodOpts;
    obj->insertionOptions = def.insertionOpts;
    const auto classes = splitClassList(def.class_names);
    simp::world::ObjectMapData data;
    if (!def.map_file.empty()) {
        if (!std::filesystem::exists(def.map_file))
            throw std::invalid_argument("semanticObjectMap [_creationOpts] map_file: '" + def.map_file +
                                        "' does not exist");
        data = simp::world::loadObjectMap(def.map_file);
        if (!classes.empty()) data = restrictToClasses(data, classes);
    } else {
        data.class_names = classes.empty() ? simp::obs::defaultClassNames() : classes;
        data.class_noise.assign(data.class_names.size(), std::nullopt);
    }
    obj->setData(data);
    return obj.release();
}

// ---------------------------------------------------------------- content
CObjectMap::CObjectMap() {
    m_data.class_names = simp::obs::defaultClassNames();
    m_data.class_noise.assign(m_data.class_names.size(), std::nullopt);
}

CObjectMap::CObjectMap(const CObjectMap& other)
    : mrpt::maps::CMetricMap(other),
      likelihoodOptions(other.likelihoodOptions),
      insertionOptions(other.insertionOptions),
      m_data(other.m_data) {
    std::lock_guard<std::mutex> lock(other.m_cache_mutex);
    m_model = other.m_model;  // immutable, shared
}

CObjectMap& CObjectMap::operator=(const CObjectMap& other) {
    if (this == &other) return *this;
    mrpt::maps::CMetricMap::operator=(other);
    likelihoodOptions = other.likelihoodOptions;
    insertionOptions = other.insertionOptions;
    m_data = other.m_data;
    std::shared_ptr<const SensorModel> model;
    {
        std::lock_guard<std::mutex> lock(other.m_cache_mutex);
        model = other.m_model;
    }
    std::lock_guard<std::mutex> lock(m_cache_mutex);
    m_model = model;
    m_warned_empty = false;
    m_inserter.reset();  // mapping state is not copied
    return *this;
}

void CObjectMap::setData(const simp::world::ObjectMapData& data) {
    // Build (and so validate) the model before touching the current content.
    const auto params = likelihoodOptions.modelParams();
    auto model = std::make_shared<const SensorModel>(data, params);
    std::lock_guard<std::mutex> lock(m_cache_mutex);
    m_data = data;
    m_model = std::move(model);
    m_warned_empty = false;
    m_inserter.reset();  // the next insertion starts from the new content
}

void CObjectMap::internal_clear() {
    const auto classes = m_data.class_names;
    const auto noise = m_data.class_noise;
    simp::world::ObjectMapData empty;
    empty.class_names = classes;
    empty.class_noise = noise;
    setData(empty);
}

std::string CObjectMap::asString() const {
    return "simp::maps::CObjectMap: " + std::to_string(m_data.objects.size()) + " objects, " +
           std::to_string(m_data.class_names.size()) + " classes, sensor model " +
           toString(likelihoodOptions.sensor_model);
}

simp::world::ObjectMapData restrictToClasses(const simp::world::ObjectMapData& data,
                                             const std::vector<std::string>& class_names) {
    simp::world::ObjectMapData out;
    out.class_names = class_names;
    out.class_noise.assign(class_names.size(), std::nullopt);
    for (std::size_t c = 0; c < class_names.size(); ++c) {
        const int old_id = data.classId(class_names[c]);
        if (old_id >= 0 && static_cast<std::size_t>(old_id) < data.class_noise.size())
            out.class_noise[c] = data.class_noise[static_cast<std::size_t>(old_id)];
    }
    for (const auto& obj : data.objects) {
        if (obj.class_id < 0 || static_cast<std::size_t>(obj.class_id) >= data.class_names.size()) continue;
        const auto it = std::find(class_names.begin(), class_names.end(),
                                  data.class_names[static_cast<std::size_t>(obj.class_id)]);
        if (it == class_names.end()) continue;
        auto copy = obj;
        copy.class_id = static_cast<int>(it - class_names.begin());
        out.objects.push_back(copy);
    }
    return out;
}

}  // namespace simp::maps
