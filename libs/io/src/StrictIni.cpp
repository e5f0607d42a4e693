/// \file StrictIni.cpp
#include <simp/io/StrictIni.h>
#include <simp/io/StrictNumber.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace simp::io {
namespace {

/// Largest .ini read (the project's are < 20 KB).
constexpr std::uintmax_t kMaxIniBytes = 1u << 20;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

/// How MRPT's read_* format their defaults: "%.16e" (double), "%.10e" (float), "%i"/"%lu" (integers),
/// "0"/"1" (bool and small integers).
enum class Expect { Text, Number, Integer, IntegerOrBool };

Expect expectedFromDefault(const std::string& def) {
    static const std::regex floating(R"(-?(\d\.\d{10}|\d\.\d{16})e[+-]\d{2,3}|-?inf|-?nan)");
    static const std::regex integer(R"(-?\d+)");
    if (def == "0" || def == "1") return Expect::IntegerOrBool;
    if (std::regex_match(def, floating)) return Expect::Number;
    if (std::regex_match(def, integer)) return Expect::Integer;
    return Expect::Text;
}

/// MRPT's readString drops a trailing "// comment" after a blank; compare what it will parse.
std::string withoutComment(const std::string& v) {
    const auto pos = v.find("//");
    if (pos != std::string::npos && pos > 0 && std::isspace(static_cast<unsigned char>(v[pos - 1]))) return v.substr(0, pos);
    return v;
}

void checkSyntax(const std::string& text, const std::string& name) {
    if (text.find('\0') != std::string::npos) throw std::invalid_argument(name + ": not a text .ini file (holds NUL bytes)");
    std::istringstream in(text);
    std::string section;
    bool any_section = false;
    std::map<std::string, std::set<std::string>> seen;
    int n = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++n;
        const std::string line = trim(raw);
        const std::string at = name + ":" + std::to_string(n) + ": ";
        if (line.empty() || line[0] == ';' || line[0] == '#' || line.rfind("//", 0) == 0) continue;
        if (line[0] == '[') {
            const auto close = line.find(']');
            const std::string rest = close == std::string::npos ? "" : trim(line.substr(close + 1));
            if (close == std::string::npos || close == 1 || !(rest.empty() || rest[0] == ';' || rest[0] == '#' || rest.rfind("//", 0) == 0))
                throw std::invalid_argument(at + "'" + line + "' is not a [section] header");
            section = trim(line.substr(1, close - 1));
            if (section.empty()) throw std::invalid_argument(at + "empty section name");
            if (seen.count(lower(section))) throw std::invalid_argument(at + "section [" + section + "] appears twice");
            seen[lower(section)];
            any_section = true;
            continue;
        }
        const auto eq = line.find('=');
        if (eq == std::string::npos)
            throw std::invalid_argument(at + "'" + line.substr(0, 60) + "' is neither [section] nor key = value");
        const std::string key = trim(line.substr(0, eq));
        if (key.empty()) throw std::invalid_argument(at + "'" + line.substr(0, 60) + "' has no key before '='");
        if (!any_section) throw std::invalid_argument(at + "key '" + key + "' is outside any [section]");
        if (!seen[lower(section)].insert(lower(key)).second)
            throw std::invalid_argument(at + "[" + section + "] key '" + key + "' is set twice");
    }
    if (!any_section) throw std::invalid_argument(name + ": no [section] (not an MRPT .ini file)");
}

}  // namespace

StrictIni::StrictIni() = default;

StrictIni::StrictIni(const std::string& text, const std::string& name) : m_name(name) {
    checkSyntax(text, name);
    m_ini.setContent(text);
}

namespace {
std::string readIniFile(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) throw std::invalid_argument("config file '" + path + "' does not exist");
    if (!fs::is_regular_file(path, ec)) throw std::invalid_argument("config file '" + path + "' is not a regular file");
    if (fs::file_size(path, ec) > kMaxIniBytes)
        throw std::invalid_argument(path + ": larger than 1 MiB (not an .ini file)");
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    if (!f) throw std::invalid_argument("config file '" + path + "' cannot be read");
    return s.str();
}
}  // namespace

StrictIni::StrictIni(const std::string& path) {
    if (path.empty()) return;
    m_name = path;
    const std::string text = readIniFile(path);
    checkSyntax(text, path);
    m_ini.setContent(text);
}

bool StrictIni::empty() const {
    std::vector<std::string> sections;
    getAllSections(sections);
    return sections.empty();
}

std::string StrictIni::where(const std::string& section, const std::string& key) const {
    return m_name + ": [" + section + "] " + key;
}

std::string StrictIni::readString(const std::string& section, const std::string& name, const std::string& defaultStr,
                                  bool failIfNotFound) const {
    m_read[lower(section)].insert(lower(name));
    std::vector<std::string> keys;
    m_ini.getAllKeys(section, keys);
    const bool present = std::any_of(keys.begin(), keys.end(), [&](const std::string& k) { return lower(k) == lower(name); });
    if (!present) {
        if (failIfNotFound) throw std::invalid_argument(where(section, name) + ": required key is missing");
        return defaultStr;
    }
    const std::string value = m_ini.read_string(section, name, defaultStr);
    const std::string text = trim(withoutComment(value));
    switch (expectedFromDefault(defaultStr)) {
        case Expect::Text: break;
        case Expect::Number:
            if (!parseFiniteNumber(text)) throw std::invalid_argument(where(section, name) + " = '" + text + "' is not a finite number");
            break;
        case Expect::Integer: {
            // read_int's atoi overflows silently: an int default ("%i") needs a value that fits an int.
            const auto v = parseWholeInteger(text);
            const auto d = parseWholeInteger(defaultStr);
            const bool int_default = d && *d >= std::numeric_limits<int>::min() && *d <= std::numeric_limits<int>::max();
            if (!v) throw std::invalid_argument(where(section, name) + " = '" + text + "' is not an integer");
            if (int_default && (*v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max()))
                throw std::invalid_argument(where(section, name) + " = " + text + " is out of the integer range");
            break;
        }
        case Expect::IntegerOrBool: {
            const std::string l = lower(text);
            const auto v = parseWholeInteger(text);
            if (!v && l != "true" && l != "false" && l != "yes" && l != "no")
                throw std::invalid_argument(where(section, name) + " = '" + text + "' is not an integer or true/false");
            if (v && (*v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max()))
                throw std::invalid_argument(where(section, name) + " = " + text + " is out of the integer range");
            break;
        }
    }
    return value;
}

double StrictIni::readNumber(const std::string& section, const std::string& key, double def, double lo, double hi) const {
    const std::string text = trim(withoutComment(readString(section, key, "", false)));
    if (text.empty()) return def;
    return parseNumber(text, where(section, key), lo, hi);
}

std::int64_t StrictIni::readInteger(const std::string& section, const std::string& key, std::int64_t def, std::int64_t lo,
                                    std::int64_t hi) const {
    const std::string text = trim(withoutComment(readString(section, key, "", false)));
    if (text.empty()) return def;
    return parseInteger(text, where(section, key), lo, hi);
}

bool StrictIni::readBool(const std::string& section, const std::string& key, bool def) const {
    const std::string text = trim(withoutComment(readString(section, key, "", false)));
    if (text.empty()) return def;
    return parseBool(text, where(section, key));
}

void StrictIni::checkUnknown(const std::vector<std::string>& other_sections) const {
    std::vector<std::string> sections;
    getAllSections(sections);
    for (const auto& sec : sections) {
        const auto it = m_read.find(lower(sec));
        if (it == m_read.end()) {
            const bool declared = std::any_of(other_sections.begin(), other_sections.end(),
                                              [&](const std::string& o) { return lower(o) == lower(sec); });
            if (declared) continue;
            std::string known;
            for (const auto& [s, keys] : m_read) known += (known.empty() ? "" : ", ") + ("[" + s + "]");
            for (const auto& o : other_sections) known += (known.empty() ? "" : ", ") + ("[" + o + "]");
            throw std::invalid_argument(m_name + ": unknown section [" + sec + "] (this app reads " +
                                        (known.empty() ? "no section" : known) + ")");
        }
        std::vector<std::string> keys;
        getAllKeys(sec, keys);
        for (const auto& k : keys) {
            if (it->second.count(lower(k))) continue;
            std::string known;
            for (const auto& x : it->second) known += (known.empty() ? "" : ", ") + x;
            throw std::invalid_argument(m_name + ": [" + sec + "] unknown key '" + k + "' (known keys: " + known + ")");
        }
    }
}

void StrictIni::loadChecked(const std::function<void(const StrictIni&)>& load,
                            const std::vector<std::string>& other_sections) const {
    try {
        load(*this);
    } catch (const std::exception& e) {
        std::string m = e.what();
        // MRPT's exceptions carry a location block: keep the message lines only.
        const auto msg = m.find("Message:");
        if (msg != std::string::npos) m = trim(m.substr(msg + 8, m.find('\n', msg) - msg - 8));
        throw std::invalid_argument(m.rfind(m_name, 0) == 0 ? m : m_name + ": " + m);
    }
    checkUnknown(other_sections);
}

void StrictIni::getAllSections(std::vector<std::string>& sections) const { m_ini.getAllSections(sections); }
void StrictIni::getAllKeys(const std::string& section, std::vector<std::string>& keys) const { m_ini.getAllKeys(section, keys); }
void StrictIni::clear() { m_ini.clear(); }
void StrictIni::writeString(const std::string& section, const std::string& name, const std::string& str) {
    m_ini.write(section, name, str);
}

}  // namespace simp::io
