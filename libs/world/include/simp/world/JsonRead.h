#pragma once
/// \file JsonRead.h
/// Reading and writing the project's JSON files with error messages that name the file,
/// the entry and the key ("objects.json: objects[3].size_m: expected 3 positive numbers").
/// Shared by libs/world (world directories, the authors' map format), libs/detector_io (detector
/// files, camera rigs) and libs/labels (camera frames, Omni3D labels).

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace simp::world {

/// Throws std::runtime_error("<file>: <key>: <what>") ("<file>: <what>" when `key` is empty).
[[noreturn]] void failAt(const std::string& file, const std::string& key, const std::string& what);

/// Parses a whole file; errors name the file (missing, unreadable, invalid JSON).
nlohmann::json readJsonFile(const std::string& path);

/// How writeJsonFile() lays out the text (the content is the same JSON either way).
enum class JsonLayout {
    Readable,  ///< compact, one line per element of containers that hold containers (diffable)
    Indent1    ///< nlohmann's dump(1): every value on its own line, indent 1
};
/// Writes `j` (keys in insertion order) followed by a newline; creates parent folders;
/// errors name the file.
void writeJsonFile(const nlohmann::ordered_json& j, const std::string& path,
                   JsonLayout layout = JsonLayout::Readable);

/// obj[key]; `key_path` is the full key used in messages (e.g. "objects[3].size_m").
/// \throw "<file>: <key_path>: missing key" when absent.
const nlohmann::json& requireKey(const nlohmann::json& obj, const std::string& key, const std::string& file,
                                 const std::string& key_path);
/// A finite number.
double asNumber(const nlohmann::json& v, const std::string& file, const std::string& key_path);
/// An integer (a JSON integer, or a float with an integral value).
long long asInteger(const nlohmann::json& v, const std::string& file, const std::string& key_path);
std::string asString(const nlohmann::json& v, const std::string& file, const std::string& key_path);
/// An array of exactly n finite numbers (n = 0: any length); `expect` completes the message.
std::vector<double> asNumbers(const nlohmann::json& v, std::size_t n, const std::string& file,
                              const std::string& key_path, const std::string& expect);
/// An array of exactly n finite numbers; a wrong element is named ("<key_path>[i]").
std::vector<double> asNumberArray(const nlohmann::json& v, std::size_t n, const std::string& file,
                                  const std::string& key_path);
/// A 3x3 matrix as [[r0], [r1], [r2]] or 9 numbers, row-major.
Eigen::Matrix3d asMatrix3(const nlohmann::json& v, const std::string& file, const std::string& key_path);
/// Eigen values as JSON: a matrix as an array of rows, a vector as an array.
nlohmann::ordered_json toJson(const Eigen::Matrix3d& M);
nlohmann::ordered_json toJson(const Eigen::Vector3d& v);

}  // namespace simp::world
