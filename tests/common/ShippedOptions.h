#pragma once
/// \file ShippedOptions.h
/// What every shipped config_ini/*.ini sets, pinned: tests/data/options/shipped_values.txt holds one
/// line "FILE [SECTION] key = value" per key (numbers to 17 digits) as the hand-written loaders
/// read them before the options moved to io::OptionTable (and "(defaults)" for no .ini). A test
/// loads each file with today's loader and compares its table's values() with those lines.

#include <simp/io/OptionTable.h>
#include <simp/io/StrictIni.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace simp_test {

/// The pinned lines of `file` whose section is `section`, sorted.
inline std::vector<std::string> shippedValues(const std::string& file, const std::string& section) {
    std::ifstream in(std::string(SIMP_SOURCE_DIR) + "/tests/data/options/shipped_values.txt");
    std::vector<std::string> lines;
    const std::string prefix = file + " [" + section + "] ";
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) == 0) lines.push_back(line);
    std::sort(lines.begin(), lines.end());
    return lines;
}

/// The same lines made from `options` by its table, sorted.
template <class Options>
std::vector<std::string> valueLines(const std::string& file, const std::string& section, const simp::io::OptionTable<Options>& table,
                                    const Options& options) {
    std::vector<std::string> lines;
    for (const auto& [key, value] : table.values(options)) lines.push_back(file + " [" + section + "] " + key + " = " + value);
    std::sort(lines.begin(), lines.end());
    return lines;
}

/// The lines of `options` equal the pinned lines of `file` [section]: false, and `report` holds the lines
/// to pin (or the difference) otherwise. Use: EXPECT_TRUE(matchesPinned(...)) << report.
template <class Options>
bool matchesPinned(const std::string& file, const simp::io::OptionTable<Options>& table, const Options& options, std::string& report) {
    const auto expected = shippedValues(file, table.section());
    const auto lines = valueLines(file, table.section(), table, options);
    if (lines == expected && expected.size() == table.keys().size()) return true;
    report = file + " [" + table.section() + "] should be pinned (tests/data/options/shipped_values.txt) as:\n";
    for (const auto& l : lines) report += l + "\n";
    return false;
}

/// The text of doc/NAME (its key tables are generated: OptionTable::markdown()).
inline std::string docText(const std::string& name) {
    std::ifstream in(std::string(SIMP_SOURCE_DIR) + "/doc/" + name);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// config_ini/NAME, read strictly.
inline std::string shippedIni(const std::string& name) { return std::string(SIMP_SOURCE_DIR) + "/config_ini/" + name; }

}  // namespace simp_test
