#include <simp/model/LocalizationMethods.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace simp::model {

const std::vector<LocalizationMethod>& localizationMethods() {
    using T = SensorModelType;
    // The one declaration; every list of names, check and label derives from it.
    static const std::vector<LocalizationMethod> methods{
        {"simp", "Ours", T::Simp, false},  {"edt", "EDT-MCL", T::Edt, false},
        {"d", "D-MCL", T::D, false},       {"o", "O-MCL", T::O, false},
        {"lidar", "LiDAR-MCL", std::nullopt, true},
        // the object model fused with the scans is the paper's
        {"simp+lidar", "Ours+LiDAR", T::Simp, true}};
    return methods;
}

const std::vector<std::string>& localizationMethodNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const auto& m : localizationMethods()) n.emplace_back(m.name);
        return n;
    }();
    return names;
}

const LocalizationMethod* findLocalizationMethod(const std::string& name) {
    for (const auto& m : localizationMethods())
        if (name == m.name) return &m;
    return nullptr;
}

const std::vector<std::string>& sensorModelTypeNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const auto& m : localizationMethods())
            if (m.isObjectModelAlone()) n.emplace_back(m.name);
        return n;
    }();
    return names;
}

SensorModelType parseSensorModelType(const std::string& name) {
    std::string n = name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    for (const auto& m : localizationMethods())
        if (m.isObjectModelAlone() && n == m.name) return *m.object_model;
    std::string valid;
    for (const auto& v : sensorModelTypeNames()) valid += (valid.empty() ? "" : ", ") + v;
    throw std::invalid_argument("unknown sensor model '" + name + "' (valid: " + valid + ")");
}

std::string toString(SensorModelType type) {
    for (const auto& m : localizationMethods())
        if (m.isObjectModelAlone() && *m.object_model == type) return m.name;
    return "?";
}

}  // namespace simp::model
