#pragma once
// Small file helpers shared by the simulator tests.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace simp::sim::test {

/// The whole file as bytes (empty when it cannot be read).
inline std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/// SIMP_TEST_OUTPUT_DIR/sim/<name>, removed if it existed (not created; its parent is, because
/// simulateSequence creates only the last folder and ctest may run any test first in a fresh tree).
inline std::string clearedDir(const std::string& name) {
    const auto d = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "sim" / name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d.parent_path());
    return d.string();
}

/// Same, then created empty.
inline std::string emptyDir(const std::string& name) {
    const std::string d = clearedDir(name);
    std::filesystem::create_directories(d);
    return d;
}

}  // namespace simp::sim::test
