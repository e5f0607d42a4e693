#include <simp/io/NameValueList.h>
#include <simp/maps/ConfidenceThresholds.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace simp::maps {

const ConfidenceThresholds& paperConfidenceThresholds() {
    static const ConfidenceThresholds t = {
        {"sink", 0.7},  {"door", 0.5},          {"oven", 0.7},   {"board", 0.7},  {"table", 0.6},
        {"box", 0.7},   {"potted plant", 0.7},  {"drawers", 0.4}, {"sofa", 0.8},  {"cabinet", 0.7},
        {"chair", 0.7}, {"fire extinguisher", 0.7}, {"person", 0.6}, {"desk", 0.7}};
    return t;
}

ConfidenceThresholds parseConfidenceThresholds(const std::string& text, const std::string& where) {
    ConfidenceThresholds out;
    for (const auto& [name, value] : io::parseNameValueList(text, where)) {
        if (value < 0.0 || value > 1.0)
            throw std::invalid_argument(where + ": entry '" + name + "': threshold must be in [0, 1]");
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
