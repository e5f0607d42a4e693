/// \file JsonUtil.cpp
#include "JsonUtil.h"

namespace simp::labels::detail {

std::vector<double> numbers(const json& v, std::size_t n, const std::string& file, const std::string& key_path) {
    if (!v.is_array() || v.size() != n)
        world::failAt(file, key_path, "expected an array of " + std::to_string(n) + " numbers, got " + v.dump());
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(world::asNumber(v[i], file, key_path + "[" + std::to_string(i) + "]"));
    return out;
}

Eigen::Matrix3d matrix3(const json& v, const std::string& file, const std::string& key_path) {
    Eigen::Matrix3d M;
    if (v.is_array() && v.size() == 9) {
        const auto x = numbers(v, 9, file, key_path);
        for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = x[static_cast<std::size_t>(i)];
        return M;
    }
    if (!v.is_array() || v.size() != 3) world::failAt(file, key_path, "expected a 3x3 matrix [[..],[..],[..]] or 9 numbers");
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
