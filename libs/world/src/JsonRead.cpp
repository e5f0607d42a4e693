#include <simp/world/JsonRead.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace simp::world {

using nlohmann::json;

void failAt(const std::string& file, const std::string& key, const std::string& what) {
    throw std::runtime_error(file + ": " + (key.empty() ? std::string() : key + ": ") + what);
}

json readJsonFile(const std::string& path) {
    if (!std::filesystem::exists(path)) failAt(path, "", "file not found");
    if (!std::filesystem::is_regular_file(path)) failAt(path, "", "not a regular file");
    std::ifstream in(path);
    if (!in) failAt(path, "", "cannot open for reading");
    try {
        return json::parse(in);
    } catch (const json::exception& e) {  // parse errors and number overflow (out_of_range 406)
        failAt(path, "", std::string("invalid JSON: ") + e.what());
    }
}

namespace {

/// Compact text, one line per element for containers of containers (readable, diffable).
void dumpReadable(const nlohmann::ordered_json& j, const std::string& indent, std::string& out) {
    const auto isContainer = [](const nlohmann::ordered_json& e) { return e.is_object() || e.is_array(); };
    const bool nested = (j.is_object() || j.is_array()) && !j.empty() &&
                        (j.is_object() ? std::any_of(j.begin(), j.end(), isContainer) || indent.empty()
                                       : std::any_of(j.begin(), j.end(), isContainer));
    if (!nested || indent.size() >= 4) {
        out += j.dump();
        return;
    }
    const std::string inner = indent + "  ";
    out += j.is_object() ? "{\n" : "[\n";
    std::size_t k = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++k) {
        out += inner;
        if (j.is_object()) out += nlohmann::ordered_json(it.key()).dump() + ": ";
        dumpReadable(*it, inner, out);
        out += (k + 1 < j.size()) ? ",\n" : "\n";
    }
    out += indent + (j.is_object() ? "}" : "]");
}

}  // namespace

void writeJsonFile(const nlohmann::ordered_json& j, const std::string& path, JsonLayout layout) {
    const std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream out(path);
    if (!out) failAt(path, "", "cannot open for writing");
    std::string text;
    if (layout == JsonLayout::Indent1)
        text = j.dump(1);
    else
        dumpReadable(j, "", text);
    out << text << "\n";
    if (!out) failAt(path, "", "write failed");
}

const json& requireKey(const json& obj, const std::string& key, const std::string& file,
                    const std::string& key_path) {
    if (!obj.is_object()) failAt(file, key_path, "expected a JSON object around this key");
    const auto it = obj.find(key);
    if (it == obj.end()) failAt(file, key_path, "missing key");
    return *it;
}

double asNumber(const json& v, const std::string& file, const std::string& key_path) {
    if (!v.is_number()) failAt(file, key_path, "expected a number, got " + v.dump());
    const double d = v.get<double>();
    if (!std::isfinite(d)) failAt(file, key_path, "expected a finite number");
    return d;
}

long long asInteger(const json& v, const std::string& file, const std::string& key_path) {
    if (v.is_number_unsigned() && v.get<unsigned long long>() > 9e15)
        failAt(file, key_path, "integer " + v.dump() + " out of range");
    if (v.is_number_integer()) return v.get<long long>();
    if (v.is_number_float()) {
        const double d = v.get<double>();
        if (std::isfinite(d) && d == std::floor(d) && std::abs(d) < 9e15) return static_cast<long long>(d);
    }
    failAt(file, key_path, "expected an integer, got " + v.dump());
}

std::string asString(const json& v, const std::string& file, const std::string& key_path) {
    if (!v.is_string()) failAt(file, key_path, "expected a string, got " + v.dump());
    return v.get<std::string>();
}

std::vector<double> asNumbers(const json& v, std::size_t n, const std::string& file,
                              const std::string& key_path, const std::string& expect) {
    if (!v.is_array() || (n != 0 && v.size() != n)) failAt(file, key_path, "expected " + expect);
    std::vector<double> out;
    out.reserve(v.size());
    for (const auto& e : v) {
        if (!e.is_number()) failAt(file, key_path, "expected " + expect);
        const double d = e.get<double>();
        if (!std::isfinite(d)) failAt(file, key_path, "expected " + expect + " (got a non-finite value)");
        out.push_back(d);
    }
    return out;
}

std::vector<double> asNumberArray(const json& v, std::size_t n, const std::string& file, const std::string& key_path) {
    if (!v.is_array() || v.size() != n)
        failAt(file, key_path, "expected an array of " + std::to_string(n) + " numbers, got " + v.dump());
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(asNumber(v[i], file, key_path + "[" + std::to_string(i) + "]"));
    return out;
}

Eigen::Matrix3d asMatrix3(const json& v, const std::string& file, const std::string& key_path) {
    Eigen::Matrix3d M;
    if (v.is_array() && v.size() == 9) {
        const auto x = asNumberArray(v, 9, file, key_path);
        for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = x[static_cast<std::size_t>(i)];
        return M;
    }
    if (!v.is_array() || v.size() != 3) failAt(file, key_path, "expected a 3x3 matrix [[..],[..],[..]] or 9 numbers");
    for (int r = 0; r < 3; ++r) {
        const auto row = asNumberArray(v[static_cast<std::size_t>(r)], 3, file, key_path + "[" + std::to_string(r) + "]");
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

}  // namespace simp::world
