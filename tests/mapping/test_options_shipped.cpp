/// \file test_options_shipped.cpp
/// config_ini/mapping.ini (and no .ini) gives the values the hand-written loader gave
/// (tests/data/options/shipped_values.txt); the keys are declared once in MappingOptions::table().
#include "common/ShippedOptions.h"

#include <gtest/gtest.h>
#include <simp/mapping/MappingOptions.h>

using simp::mapping::MappingOptions;

TEST(MappingOptionsShipped, EveryIniGivesThePinnedValues) {
    const auto& table = MappingOptions::table();
    EXPECT_EQ(simp_test::valueLines("(defaults)", "mapping", table, MappingOptions{}), simp_test::shippedValues("(defaults)", "mapping"));
    const simp::io::StrictIni cfg(simp_test::shippedIni("mapping.ini"));
    MappingOptions o;
    o.loadFromConfigFile(cfg, "mapping");
    cfg.checkUnknown();
    const auto expected = simp_test::shippedValues("mapping.ini", "mapping");
    ASSERT_EQ(expected.size(), table.keys().size());
    EXPECT_EQ(simp_test::valueLines("mapping.ini", "mapping", table, o), expected);
}

TEST(MappingOptionsShipped, DocumentedKeyTableIsTheDeclaration) {
    const std::string table = MappingOptions::table().markdown(MappingOptions{});
    EXPECT_NE(simp_test::docText("mapping.md").find(table), std::string::npos) << "doc/mapping.md should hold:\n" << table;
}
