/// \file StrictNumber.cpp
#include <simp/io/StrictNumber.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace simp::io {
namespace {

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

}  // namespace

std::optional<double> parseFiniteNumber(const std::string& text) {
    const std::string t = trimmed(text);
    if (t.empty()) return std::nullopt;
    // strtod also takes "inf", "nan", hex floats and leading blanks: only plain decimal text here.
    for (char c : t)
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E'))
            return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<std::int64_t> parseWholeInteger(const std::string& text) {
    const std::string t = trimmed(text);
    const std::size_t digits_from = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
    if (t.size() <= digits_from) return std::nullopt;
    for (std::size_t i = digits_from; i < t.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(t[i]))) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (end != t.c_str() + t.size() || errno == ERANGE) return std::nullopt;
    return static_cast<std::int64_t>(v);
}

std::string numberText(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

std::string rangeText(double lo, double hi) { return "[" + numberText(lo) + ", " + numberText(hi) + "]"; }

double parseNumber(const std::string& text, const std::string& what, double lo, double hi) {
    const auto v = parseFiniteNumber(text);
    if (!v) throw std::invalid_argument(what + ": '" + text + "' is not a finite number");
    if (!(*v >= lo && *v <= hi)) throw std::invalid_argument(what + ": " + trimmed(text) + " must be in " + rangeText(lo, hi));
    return *v;
}

std::int64_t parseInteger(const std::string& text, const std::string& what, std::int64_t lo, std::int64_t hi) {
    const auto v = parseWholeInteger(text);
    if (!v) {
        const auto d = parseFiniteNumber(text);
        throw std::invalid_argument(what + ": '" + text + "' is not an integer" +
                                    (d ? " in " + rangeText(static_cast<double>(lo), static_cast<double>(hi)) : ""));
    }
    if (*v < lo || *v > hi)
        throw std::invalid_argument(what + ": " + trimmed(text) + " must be in " +
                                    rangeText(static_cast<double>(lo), static_cast<double>(hi)));
    return *v;
}

bool parseBool(const std::string& text, const std::string& what) {
    std::string t = trimmed(text);
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (t == "true" || t == "yes" || t == "1") return true;
    if (t == "false" || t == "no" || t == "0") return false;
    throw std::invalid_argument(what + ": '" + text + "' is not a boolean (true/false)");
}

}  // namespace simp::io
