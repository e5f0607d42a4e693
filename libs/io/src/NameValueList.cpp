#include <simp/io/NameValueList.h>
#include <simp/io/StrictNumber.h>

#include <sstream>
#include <stdexcept>

namespace simp::io {

std::string trimIniValue(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n\"");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\n\"");
    return s.substr(b, e - b + 1);
}


std::vector<std::pair<std::string, double>> parseNameValueList(const std::string& text, const std::string& where) {
    std::vector<std::pair<std::string, double>> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const std::string entry = trimIniValue(item);
        if (entry.empty()) continue;
        const auto colon = entry.rfind(':');
        if (colon == std::string::npos)
            throw std::invalid_argument(where + ": entry '" + entry + "' is not of the form name:value");
        const std::string name = trimIniValue(entry.substr(0, colon));
        const std::string value_text = trimIniValue(entry.substr(colon + 1));
        if (name.empty()) throw std::invalid_argument(where + ": entry '" + entry + "' has an empty class name");
        const auto value = parseFiniteNumber(value_text);
        if (!value)
            throw std::invalid_argument(where + ": entry '" + entry + "': '" + value_text + "' is not a finite number");
        out.emplace_back(name, *value);
    }
    return out;
}

}  // namespace simp::io
