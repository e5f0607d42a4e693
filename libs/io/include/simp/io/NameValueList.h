#pragma once
/// \file NameValueList.h
/// The per-class list syntax of the .ini files: "name:value, name:value, ..." (class names may
/// contain spaces; the value follows the last ':'; surrounding blanks and quotes are ignored).

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace simp::io {

/// `s` without surrounding blanks and double quotes (how the .ini values are compared).
std::string trimIniValue(const std::string& s);

/// The entries of `text` in order (a name may repeat; callers decide). Values are finite numbers.
/// \throw std::invalid_argument starting with `where` and naming the entry when it has no ':',
///        an empty name, or a value that is not a finite number.
std::vector<std::pair<std::string, double>> parseNameValueList(const std::string& text, const std::string& where);

/// The value a per-class list gives `name`, or `fallback` when the list does not name it.
template <class Value>
Value valueOr(const std::map<std::string, Value>& per_class, const std::string& name, Value fallback) {
    const auto it = per_class.find(name);
    return it == per_class.end() ? fallback : it->second;
}

}  // namespace simp::io
