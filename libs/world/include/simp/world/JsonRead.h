#pragma once
/// \file JsonRead.h
/// Private helpers of libs/world: read JSON files with error messages that name the file,
/// the entry and the key ("objects.json: objects[3].size_m: expected 3 positive numbers").

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace simp::world::detail {

using nlohmann::json;

/// Throws std::runtime_error("<file>: <key>: <what>").
[[noreturn]] void fail(const std::string& file, const std::string& key, const std::string& what);

/// Parses a whole file; errors name the file (missing, unreadable, invalid JSON).
json readJsonFile(const std::string& path);
/// Writes `j` pretty-printed (indent 2), keys in insertion order; creates parent folders;
/// errors name the file.
void writeJsonFile(const nlohmann::ordered_json& j, const std::string& path);

/// obj[key]; `key_path` is the full key used in messages (e.g. "objects[3].size_m").
const json& require(const json& obj, const std::string& key, const std::string& file,
                    const std::string& key_path);
/// A finite number.
double asNumber(const json& v, const std::string& file, const std::string& key_path);
/// An integer (a JSON integer, or a float with an integral value).
long long asInteger(const json& v, const std::string& file, const std::string& key_path);
std::string asString(const json& v, const std::string& file, const std::string& key_path);
/// An array of exactly n finite numbers (n = 0: any length); `expect` completes the message.
std::vector<double> asNumbers(const json& v, std::size_t n, const std::string& file,
                              const std::string& key_path, const std::string& expect);

}  // namespace simp::world::detail
