#include <simp/maps/SensorModelTypes.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace simp::maps {

SensorModelType parseSensorModelType(const std::string& name) {
    std::string n = name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    if (n == "simp") return SensorModelType::Simp;
    if (n == "edt") return SensorModelType::Edt;
    if (n == "d") return SensorModelType::D;
    if (n == "o") return SensorModelType::O;
    throw std::invalid_argument("unknown sensor model '" + name + "' (valid: simp, edt, d, o)");
}

std::string toString(SensorModelType type) {
    switch (type) {
        case SensorModelType::Simp: return "simp";
        case SensorModelType::Edt: return "edt";
        case SensorModelType::D: return "d";
        case SensorModelType::O: return "o";
    }
    return "?";
}

}  // namespace simp::maps
