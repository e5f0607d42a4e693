#include <mrpt/config/CConfigFileBase.h>
#include <simp/io/NameValueList.h>
#include <simp/io/StrictIni.h>
#include <simp/maps/CObjectMap.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace simp::maps {

namespace {
/// "name:value, ..." sorted by name, numbers to `precision` digits (formatConfidenceThresholds' form).
std::string thresholdsText(const ConfidenceThresholds& thresholds, int precision) {
    std::ostringstream s;
    s.precision(precision);
    for (const auto& [name, v] : thresholds) s << (s.tellp() > 0 ? ", " : "") << name << ":" << v;
    return s.str();
}
}  // namespace

const io::OptionTable<CObjectMap::TLikelihoodOptions>& CObjectMap::TLikelihoodOptions::table() {
    using O = TLikelihoodOptions;
    using io::ValueRange;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("<prefix>_likelihoodOpts")
            .custom(
                "sensor_model", "", io::option_text::choices(model::sensorModelTypeNames()), "the 3D-object sensor model (case-insensitive)",
                [](O& o, const std::string& text, const std::string& at) {
                    try {
                        o.sensor_model = model::parseSensorModelType(text);
                    } catch (const std::invalid_argument& e) {
                        throw std::invalid_argument(at + ": " + e.what());
                    }
                },
                [](const O& o, int) { return model::toString(o.sensor_model); })
            .number("eta", &O::eta, "", ValueRange::open(0, 1), "Eq. combined: likelihood of a false association")
            .custom(
                "confidence_thresholds", "", "name:value, ...", "`name:value` pairs separated by commas (class names may contain spaces); each entry overrides that class's "
                "threshold, the others keep the paper's value (`nmcl.config`)",
                [](O& o, const std::string& text, const std::string& at) {
                    for (const auto& [name, value] : parseConfidenceThresholds(text, at)) o.confidence_thresholds[name] = value;
                },
                [](const O& o, int precision) { return thresholdsText(o.confidence_thresholds, precision); })
            .number("default_confidence_threshold", &O::default_confidence_threshold, "", ValueRange::between(0, 1),
                    "for classes in no table")
            .number("mp_resolution_m", &O::mp_resolution_m, "m", ValueRange::positive(), "m_p raster cell")
            .number("mp_min_probability", &O::mp_min_probability, "", ValueRange::open(0, 1), "m_p support: p_o below this counts as 0")
            .flag("skip_classes_without_noise", &O::skip_classes_without_noise, "true: ignore classes without a noise model instead of throwing (see \"Bad input\")")
            .number("unmodelled_noise_std_m", &O::unmodelled_noise_std_m, "m", ValueRange::atLeast(0),
                    "> 0: isotropic noise of objects without a noise model; 0 = skipped (the paper)")
            .number("mp_centre_noise_floor", &O::mp_centre_noise_floor, "", ValueRange::between(0, 1),
                    "> 0: each noise model less its object's footprint (a centre noise), floored at this fraction of its std; 0 = as is (the paper)")
            .number("edt_sigma_m", &O::edt_sigma_m, "m", ValueRange::positive(), "EDT baseline: sigma of the centre distance; 6 px at 0.05 m, HSMCL's sigma_obs in the paper's Table")
            .number("edt_max_distance_m", &O::edt_max_distance_m, "m", ValueRange::positive(), "EDT baseline: distance clamp")
            .number("edt_resolution_m", &O::edt_resolution_m, "m", ValueRange::positive(), "EDT baseline: raster cell")
            .number("noise_reference_range_m", &O::noise_reference_range_m, "m", ValueRange::atLeast(0),
                    "detections farther than this are scored with the noise widened by range / this; 0 = off")
            .number("yaw_sigma_rad", &O::yaw_sigma_rad, "rad", ValueRange::atLeast(0),
                    "> 0: a detected box's yaw is scored against its map object's with this std (4-fold, at most 1 nat; simp model); 0 = off (the paper)");
    return t;
}

void CObjectMap::TLikelihoodOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                                        const std::string& section) {
    table().load(source, section, *this);
}

void CObjectMap::TLikelihoodOptions::dumpToTextStream(std::ostream& out) const { table().dump(*this, out); }

double CObjectMap::TLikelihoodOptions::thresholdOf(const std::string& class_name) const {
    return io::valueOr(confidence_thresholds, class_name, default_confidence_threshold);
}

SensorModelParams CObjectMap::TLikelihoodOptions::modelParams() const {
    SensorModelParams p;
    p.type = sensor_model;
    p.eta = eta;
    p.mp.resolution_m = mp_resolution_m;
    p.mp.min_probability = mp_min_probability;
    p.mp.skip_classes_without_noise = skip_classes_without_noise;
    p.mp.unmodelled_noise_std_m = unmodelled_noise_std_m;
    p.mp.centre_noise_floor = mp_centre_noise_floor;
    p.edt_sigma_m = edt_sigma_m;
    p.edt_max_distance_m = edt_max_distance_m;
    p.edt_resolution_m = edt_resolution_m;
    p.noise_reference_range_m = noise_reference_range_m;
    p.yaw_sigma_rad = yaw_sigma_rad;
    return p;
}

CObjectMap::TInsertionOptions::TInsertionOptions() {
    if (const auto factory = objectMapInserterFactory()) algorithm = factory->makeOptions();
}

CObjectMap::TInsertionOptions::TInsertionOptions(const TInsertionOptions& other)
    : mrpt::config::CLoadableOptions(other),
      algorithm(other.algorithm ? other.algorithm->clone() : nullptr),
      kept_section(other.kept_section),
      kept_keys(other.kept_keys) {}

CObjectMap::TInsertionOptions& CObjectMap::TInsertionOptions::operator=(const TInsertionOptions& other) {
    if (this == &other) return *this;
    mrpt::config::CLoadableOptions::operator=(other);
    algorithm = other.algorithm ? other.algorithm->clone() : nullptr;
    kept_section = other.kept_section;
    kept_keys = other.kept_keys;
    return *this;
}

void CObjectMap::TInsertionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                                       const std::string& section) {
    if (!algorithm)
        if (const auto factory = objectMapInserterFactory()) algorithm = factory->makeOptions();
    if (algorithm) {
        algorithm->loadFromConfigFile(source, section);
        return;
    }
    // No algorithm to know the keys: keep them for resolve() (loading a key again replaces its value).
    std::vector<std::string> names;
    source.getAllKeys(section, names);
    if (names.empty()) return;
    kept_section = section;
    for (const auto& name : names) {
        std::string value = source.read_string(section, name, "", false);
        const auto same = [&](const auto& kv) { return kv.first == name; };
        const auto it = std::find_if(kept_keys.begin(), kept_keys.end(), same);
        if (it != kept_keys.end()) it->second = std::move(value);
        else kept_keys.emplace_back(name, std::move(value));
    }
}

const ObjectMapInserterOptions& CObjectMap::TInsertionOptions::resolve(const ObjectMapInserterFactory& factory) {
    if (!algorithm) algorithm = factory.makeOptions();
    if (!kept_keys.empty()) {
        // Read as the .ini would have been, strictly: the algorithm's reads are the known keys.
        std::string text = "[" + kept_section + "]\n";
        for (const auto& [name, value] : kept_keys) text += name + " = " + value + "\n";
        const io::StrictIni ini(text, "semanticObjectMap insertion options");
        ini.loadChecked([&](const io::StrictIni& c) { algorithm->loadFromConfigFile(c, kept_section); });
        kept_keys.clear();
        kept_section.clear();
    }
    return *algorithm;
}

void CObjectMap::TInsertionOptions::dumpToTextStream(std::ostream& out) const {
    out << "\n----------- [simp::maps::CObjectMap::TInsertionOptions] ------------\n\n";
    if (algorithm) {
        algorithm->dumpToTextStream(out);
        return;
    }
    out << "(no map construction loaded: libsimp_mapping.so reads these keys when insertion starts)\n";
    for (const auto& [name, value] : kept_keys) out << name << " = " << value << "\n";
}

}  // namespace simp::maps
