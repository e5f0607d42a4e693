#pragma once
// Shared helpers of tests/world: a fresh output folder per test, file writing, throw capture.
#include <gtest/gtest.h>

#include "common/ErrorOf.h"

#include <filesystem>
#include <fstream>
#include <string>

namespace simp_test {

/// SIMP_TEST_OUTPUT_DIR/world/<suite>.<test>, emptied.
inline std::string freshDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path p =
        std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "world" / (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p.string();
}

inline void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}


}  // namespace simp_test
