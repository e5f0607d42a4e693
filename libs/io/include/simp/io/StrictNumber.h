#pragma once
/// \file StrictNumber.h
/// The one strict number parser of the project: .ini values, command-line options and list entries.
/// A number is the whole token (blanks around it allowed, nothing else), finite, and within the
/// range the caller documents. std::stod/atof/stoul accept "3x", "abc" (as 0) or "-1" (as 2^64-1).

#include <cstdint>
#include <optional>
#include <string>

namespace simp::io {

/// The whole of `text` (surrounding blanks allowed) as a finite number, or nullopt.
std::optional<double> parseFiniteNumber(const std::string& text);

/// The whole of `text` as a decimal integer (an optional sign, digits; no exponent or '.'), or nullopt
/// when it is not one or does not fit in 64 bits.
std::optional<std::int64_t> parseWholeInteger(const std::string& text);

/// A finite number in [lo, hi].
/// \throw std::invalid_argument "`what`: 'text' is not a number" / "... must be in [lo, hi]".
double parseNumber(const std::string& text, const std::string& what, double lo, double hi);

/// A decimal integer in [lo, hi] (also "5e3"-free: "5000" only).
/// \throw std::invalid_argument "`what`: 'text' is not an integer" / "... must be in [lo, hi]".
std::int64_t parseInteger(const std::string& text, const std::string& what, std::int64_t lo, std::int64_t hi);

/// true/false, yes/no, 1/0 (any case).
/// \throw std::invalid_argument "`what`: 'text' is not a boolean (true/false)".
bool parseBool(const std::string& text, const std::string& what);

/// `v` as messages print it: "70", "12.5", "1e+06" (6 significant digits; std::to_string gives "70.000000").
std::string numberText(double v);

/// "[lo, hi]" as printed in messages (integers without decimals, 1e+06 style for large values).
std::string rangeText(double lo, double hi);

}  // namespace simp::io
