#pragma once
/// \file JsonUtil.h
/// Private helpers of libs/labels on top of simp/world/JsonRead.h (which reads, writes and
/// checks JSON values with errors "<file>: <key>: <what>"): fixed-size number arrays with
/// per-element messages, 3x3 matrices, and Eigen values as JSON.

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <simp/world/JsonRead.h>

#include <string>
#include <vector>

namespace simp::labels::detail {

using nlohmann::json;

/// An array of n finite numbers.
std::vector<double> numbers(const json& v, std::size_t n, const std::string& file, const std::string& key_path);
/// A 3x3 matrix as [[r0], [r1], [r2]] or 9 numbers, row-major.
Eigen::Matrix3d matrix3(const json& v, const std::string& file, const std::string& key_path);
nlohmann::ordered_json toJson(const Eigen::Matrix3d& M);
nlohmann::ordered_json toJson(const Eigen::Vector3d& v);

}  // namespace simp::labels::detail
