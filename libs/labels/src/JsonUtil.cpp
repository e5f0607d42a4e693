/// \file JsonUtil.cpp
#include "JsonUtil.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace simp::labels::detail {

void fail(const std::string& file, const std::string& key, const std::string& what) {
    throw std::runtime_error(file + ": " + (key.empty() ? std::string() : key + ": ") + what);
}

json readJsonFile(const std::string& path) {
    if (!std::filesystem::exists(path)) fail(path, "", "file not found");
    std::ifstream in(path);
    if (!in) fail(path, "", "cannot open for reading");
    try {
        return json::parse(in);
    } catch (const json::parse_error& e) {
        fail(path, "", std::string("invalid JSON: ") + e.what());
    }
}

void writeJsonFile(const nlohmann::ordered_json& j, const std::string& path) {
    const std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream out(path);
    if (!out) fail(path, "", "cannot open for writing");
    out << j.dump(1) << "\n";
    if (!out) fail(path, "", "write failed");
}

const json& require(const json& obj, const std::string& key, const std::string& file, const std::string& key_path) {
    if (!obj.is_object()) fail(file, key_path, "expected a JSON object around this key");
    const auto it = obj.find(key);
    if (it == obj.end()) fail(file, key_path, "missing key");
    return *it;
}

double number(const json& v, const std::string& file, const std::string& key_path) {
    if (!v.is_number()) fail(file, key_path, "expected a number, got " + v.dump());
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(file, key_path, "expected a finite number");
    return x;
}

long long integer(const json& v, const std::string& file, const std::string& key_path) {
    if (v.is_number_integer()) return v.get<long long>();
    const double x = number(v, file, key_path);
    if (std::floor(x) != x) fail(file, key_path, "expected an integer, got " + v.dump());
    return static_cast<long long>(x);
}

std::string text(const json& v, const std::string& file, const std::string& key_path) {
    if (!v.is_string()) fail(file, key_path, "expected a string, got " + v.dump());
    return v.get<std::string>();
}

std::vector<double> numbers(const json& v, std::size_t n, const std::string& file, const std::string& key_path) {
    if (!v.is_array() || v.size() != n)
        fail(file, key_path, "expected an array of " + std::to_string(n) + " numbers, got " + v.dump());
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(number(v[i], file, key_path + "[" + std::to_string(i) + "]"));
    return out;
}

Eigen::Matrix3d matrix3(const json& v, const std::string& file, const std::string& key_path) {
    Eigen::Matrix3d M;
    if (v.is_array() && v.size() == 9) {
        const auto x = numbers(v, 9, file, key_path);
        for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = x[static_cast<std::size_t>(i)];
        return M;
    }
    if (!v.is_array() || v.size() != 3) fail(file, key_path, "expected a 3x3 matrix [[..],[..],[..]] or 9 numbers");
    for (int r = 0; r < 3; ++r) {
        const auto row = numbers(v[static_cast<std::size_t>(r)], 3, file, key_path + "[" + std::to_string(r) + "]");
        for (int c = 0; c < 3; ++c) M(r, c) = row[static_cast<std::size_t>(c)];
    }
    return M;
}

nlohmann::ordered_json toJson(const Eigen::Matrix3d& M) {
    nlohmann::ordered_json j = nlohmann::ordered_json::array();
    for (int r = 0; r < 3; ++r) j.push_back({M(r, 0), M(r, 1), M(r, 2)});
    return j;
}

nlohmann::ordered_json toJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace simp::labels::detail
