#pragma once
/// \file ToolArgs.h
/// Command lines of the apps and rawlog tools: `--key value` pairs, some required, --help.

#include <map>
#include <string>
#include <vector>

namespace simp::io {

struct ToolArgs {
    std::map<std::string, std::string> values;  ///< key without "--" -> value
    bool help = false;

    bool has(const std::string& key) const { return values.count(key) > 0; }
    const std::string& get(const std::string& key) const { return values.at(key); }
};

/// Parses argv; `required` and `optional` list keys without "--".
/// \throw std::invalid_argument for an unknown option, a missing value or a missing required option.
ToolArgs parseToolArgs(int argc, const char* const* argv, const std::vector<std::string>& required,
                       const std::vector<std::string>& optional);

}  // namespace simp::io
