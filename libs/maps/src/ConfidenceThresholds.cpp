#include <simp/maps/ConfidenceThresholds.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace simp::maps {
namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n\"");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\n\"");
    return s.substr(b, e - b + 1);
}

}  // namespace

const ConfidenceThresholds& paperConfidenceThresholds() {
    static const ConfidenceThresholds t = {
        {"sink", 0.7},  {"door", 0.5},          {"oven", 0.7},   {"board", 0.7},  {"table", 0.6},
        {"box", 0.7},   {"potted plant", 0.7},  {"drawers", 0.4}, {"sofa", 0.8},  {"cabinet", 0.7},
        {"chair", 0.7}, {"fire extinguisher", 0.7}, {"person", 0.6}, {"desk", 0.7}};
    return t;
}

ConfidenceThresholds parseConfidenceThresholds(const std::string& text, const std::string& where) {
    ConfidenceThresholds out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const std::string entry = trim(item);
        if (entry.empty()) continue;
        const auto colon = entry.rfind(':');
        if (colon == std::string::npos)
            throw std::invalid_argument(where + ": entry '" + entry + "' is not of the form name:value");
        const std::string name = trim(entry.substr(0, colon));
        const std::string value_text = trim(entry.substr(colon + 1));
        if (name.empty()) throw std::invalid_argument(where + ": entry '" + entry + "' has an empty class name");
        double value = 0;
        try {
            std::size_t used = 0;
            value = std::stod(value_text, &used);
            if (used != value_text.size()) throw std::invalid_argument("trailing characters");
        } catch (const std::exception&) {
            throw std::invalid_argument(where + ": entry '" + entry + "': '" + value_text + "' is not a number");
        }
        if (!std::isfinite(value) || value < 0.0 || value > 1.0)
            throw std::invalid_argument(where + ": entry '" + entry + "': threshold must be in [0, 1]");
        if (!out.emplace(name, value).second)
            throw std::invalid_argument(where + ": class '" + name + "' is given twice");
    }
    return out;
}

std::string formatConfidenceThresholds(const ConfidenceThresholds& thresholds) {
    std::ostringstream s;
    bool first = true;
    for (const auto& [name, value] : thresholds) {
        s << (first ? "" : ", ") << name << ":" << value;
        first = false;
    }
    return s.str();
}

}  // namespace simp::maps
