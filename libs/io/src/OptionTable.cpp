/// \file OptionTable.cpp
/// The non-template parts of OptionTable: strict parsing and the texts of ranges and choices.
#include <simp/io/NameValueList.h>
#include <simp/io/OptionTable.h>
#include <simp/io/StrictNumber.h>

#include <cmath>

namespace simp::io {
namespace {
/// Never a value of a real .ini: tells an absent key from an empty one with any config source.
constexpr const char* kAbsent = "\x01(absent)";

/// A bound as text: "0.5", "1e+06"; a whole number that %g would round (4294967295, not 4.29497e+09)
/// with all its digits.
std::string boundText(double v) {
    const std::string g = numberText(v);
    if (v == std::floor(v) && std::abs(v) < 1e18 && std::stod(g) != v) return std::to_string(static_cast<long long>(v));
    return g;
}
}  // namespace

bool ValueRange::contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string ValueRange::text() const {
    if (std::isinf(lo) && std::isinf(hi)) return "finite";
    if (std::isinf(hi)) return (lo_open ? "> " : ">= ") + boundText(lo);
    if (std::isinf(lo)) return (hi_open ? "< " : "<= ") + boundText(hi);
    return std::string("in ") + (lo_open ? "(" : "[") + boundText(lo) + ", " + boundText(hi) + (hi_open ? ")" : "]");
}

namespace option_text {

double number(const std::string& text, const std::string& at) {
    const auto v = parseFiniteNumber(text);
    if (!v) throw std::invalid_argument(at + " = '" + text + "' is not a finite number");
    return *v;
}

std::int64_t integer(const std::string& text, const std::string& at, double lo, double hi) {
    // A whole number also written as 5e3 or 5000.0 (the localization loaders always took those).
    std::optional<double> v;
    if (const auto i = parseWholeInteger(text)) v = static_cast<double>(*i);
    else if (const auto d = parseFiniteNumber(text); d && *d == std::floor(*d)) v = d;
    if (!v) throw std::invalid_argument(at + " = '" + text + "' is not an integer");
    if (*v < lo || *v > hi || std::abs(*v) > 9e18) throw std::invalid_argument(at + " = " + text + " is out of the integer range");
    if (const auto i = parseWholeInteger(text)) return *i;
    return static_cast<std::int64_t>(*v);
}

bool flag(const std::string& text, const std::string& at) { return parseBool(text, at); }

std::string choices(const std::vector<std::string>& names) {
    std::string s;
    for (std::size_t k = 0; k < names.size(); ++k)
        s += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + ("'" + names[k] + "'");
    return s;
}

bool read(const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key, std::string& text) {
    const std::string raw = cfg.read_string(section, key, kAbsent, false);  // StrictIni learns the key as known
    if (raw == kAbsent) return false;
    text = trimIniValue(raw);
    return true;
}

}  // namespace option_text
}  // namespace simp::io
