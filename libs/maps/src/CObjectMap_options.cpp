#include <mrpt/config/CConfigFileBase.h>
#include <simp/io/StrictIni.h>
#include <simp/maps/CObjectMap.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <stdexcept>

namespace simp::maps {

void CObjectMap::TLikelihoodOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                                        const std::string& section) {
    const std::string model_name = source.read_string(section, "sensor_model", toString(sensor_model));
    try {
        sensor_model = parseSensorModelType(model_name);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("[" + section + "] sensor_model: " + e.what());
    }
    MRPT_LOAD_CONFIG_VAR(eta, double, source, section);
    if (!(eta > 0.0 && eta < 1.0))
        throw std::invalid_argument("[" + section + "] eta = " + std::to_string(eta) + " must be in (0, 1)");

    const std::string thresholds_text = source.read_string(section, "confidence_thresholds", "");
    for (const auto& [name, value] :
         parseConfidenceThresholds(thresholds_text, "[" + section + "] confidence_thresholds"))
        confidence_thresholds[name] = value;  // override the defaults class by class
    MRPT_LOAD_CONFIG_VAR(default_confidence_threshold, double, source, section);
    if (!(default_confidence_threshold >= 0.0 && default_confidence_threshold <= 1.0))
        throw std::invalid_argument("[" + section + "] default_confidence_threshold must be in [0, 1]");

    MRPT_LOAD_CONFIG_VAR(mp_resolution_m, double, source, section);
    MRPT_LOAD_CONFIG_VAR(mp_min_probability, double, source, section);
    MRPT_LOAD_CONFIG_VAR(skip_classes_without_noise, bool, source, section);
    MRPT_LOAD_CONFIG_VAR(unmodelled_noise_std_m, double, source, section);
    if (!(unmodelled_noise_std_m >= 0.0 && std::isfinite(unmodelled_noise_std_m)))
        throw std::invalid_argument("[" + section + "] unmodelled_noise_std_m = " + std::to_string(unmodelled_noise_std_m) +
                                    " must be >= 0 (0 = off)");
    MRPT_LOAD_CONFIG_VAR(edt_sigma_m, double, source, section);
    MRPT_LOAD_CONFIG_VAR(edt_max_distance_m, double, source, section);
    MRPT_LOAD_CONFIG_VAR(edt_resolution_m, double, source, section);
    MRPT_LOAD_CONFIG_VAR(noise_reference_range_m, double, source, section);
    if (!(noise_reference_range_m >= 0.0 && std::isfinite(noise_reference_range_m)))
        throw std::invalid_argument("[" + section + "] noise_reference_range_m = " +
                                    std::to_string(noise_reference_range_m) + " must be >= 0 (0 = off)");
    const auto positive = [&](double v, const char* key) {
        if (!(v > 0.0)) throw std::invalid_argument("[" + section + "] " + key + " = " + std::to_string(v) + " must be > 0");
    };
    positive(mp_resolution_m, "mp_resolution_m");
    positive(edt_sigma_m, "edt_sigma_m");
    positive(edt_max_distance_m, "edt_max_distance_m");
    positive(edt_resolution_m, "edt_resolution_m");
    if (!(mp_min_probability > 0.0 && mp_min_probability < 1.0))
        throw std::invalid_argument("[" + section + "] mp_min_probability must be in (0, 1)");
}

void CObjectMap::TLikelihoodOptions::dumpToTextStream(std::ostream& out) const {
    out << "\n----------- [simp::maps::CObjectMap::TLikelihoodOptions] ------------\n\n";
    out << "sensor_model                            = " << toString(sensor_model) << "\n";
    LOADABLEOPTS_DUMP_VAR(eta, double);
    out << "confidence_thresholds                   = " << formatConfidenceThresholds(confidence_thresholds) << "\n";
    LOADABLEOPTS_DUMP_VAR(default_confidence_threshold, double);
    LOADABLEOPTS_DUMP_VAR(mp_resolution_m, double);
    LOADABLEOPTS_DUMP_VAR(mp_min_probability, double);
    LOADABLEOPTS_DUMP_VAR(skip_classes_without_noise, bool);
    LOADABLEOPTS_DUMP_VAR(unmodelled_noise_std_m, double);
    LOADABLEOPTS_DUMP_VAR(edt_sigma_m, double);
    LOADABLEOPTS_DUMP_VAR(edt_max_distance_m, double);
    LOADABLEOPTS_DUMP_VAR(edt_resolution_m, double);
    LOADABLEOPTS_DUMP_VAR(noise_reference_range_m, double);
}

double CObjectMap::TLikelihoodOptions::thresholdOf(const std::string& class_name) const {
    const auto it = confidence_thresholds.find(class_name);
    return it == confidence_thresholds.end() ? default_confidence_threshold : it->second;
}

SensorModelParams CObjectMap::TLikelihoodOptions::modelParams() const {
    SensorModelParams p;
    p.type = sensor_model;
    p.eta = eta;
    p.mp.resolution_m = mp_resolution_m;
    p.mp.min_probability = mp_min_probability;
    p.mp.skip_classes_without_noise = skip_classes_without_noise;
    p.mp.unmodelled_noise_std_m = unmodelled_noise_std_m;
    p.edt_sigma_m = edt_sigma_m;
    p.edt_max_distance_m = edt_max_distance_m;
    p.edt_resolution_m = edt_resolution_m;
    p.noise_reference_range_m = noise_reference_range_m;
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
