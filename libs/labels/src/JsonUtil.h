#pragma once
/// \file JsonUtil.h
/// Private helpers of libs/labels: JSON reading with errors "<file>: <key>: <what>".

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace simp::labels::detail {

using nlohmann::json;

[[noreturn]] void fail(const std::string& file, const std::string& key, const std::string& what);
json readJsonFile(const std::string& path);
void writeJsonFile(const nlohmann::ordered_json& j, const std::string& path);
const json& require(const json& obj, const std::string& key, const std::string& file, const std::string& key_path);
double number(const json& v, const std::string& file, const std::string& key_path);
long long integer(const json& v, const std::string& file, const std::string& key_path);
std::string text(const json& v, const std::string& file, const std::string& key_path);
/// An array of n finite numbers.
std::vector<double> numbers(const json& v, std::size_t n, const std::string& file, const std::string& key_path);
/// A 3x3 matrix as [[r0], [r1], [r2]] or 9 numbers, row-major.
Eigen::Matrix3d matrix3(const json& v, const std::string& file, const std::string& key_path);
nlohmann::ordered_json toJson(const Eigen::Matrix3d& M);
nlohmann::ordered_json toJson(const Eigen::Vector3d& v);

}  // namespace simp::labels::detail
