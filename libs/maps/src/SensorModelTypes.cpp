#include <simp/maps/SensorModelTypes.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <utility>

namespace simp::maps {
namespace {
/// Every model with its name, once.
constexpr std::pair<SensorModelType, const char*> kModels[] = {
    {SensorModelType::Simp, "simp"}, {SensorModelType::Edt, "edt"}, {SensorModelType::D, "d"}, {SensorModelType::O, "o"}};
}  // namespace

const std::vector<std::string>& sensorModelTypeNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const auto& [type, name] : kModels) n.emplace_back(name);
        return n;
    }();
    return names;
}

SensorModelType parseSensorModelType(const std::string& name) {
    std::string n = name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    for (const auto& [type, model] : kModels)
        if (n == model) return type;
    std::string valid;
    for (const auto& m : sensorModelTypeNames()) valid += (valid.empty() ? "" : ", ") + m;
    throw std::invalid_argument("unknown sensor model '" + name + "' (valid: " + valid + ")");
}

std::string toString(SensorModelType type) {
    for (const auto& [t, name] : kModels)
        if (t == type) return name;
    return "?";
}

}  // namespace simp::maps
