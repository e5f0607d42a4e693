/// \file test_options_shipped.cpp
/// config_ini/octomap.ini (and no .ini) gives the values the hand-written loader gave
/// (tests/data/options/shipped_values.txt); the keys are declared once in OctomapExportOptions::table().
#include "common/ShippedOptions.h"

#include <gtest/gtest.h>
#include <simp/export3d/OctomapExport.h>

using simp::export3d::OctomapExportOptions;

TEST(OctomapOptionsShipped, EveryIniGivesThePinnedValues) {
    const auto& table = OctomapExportOptions::table();
    EXPECT_EQ(simp_test::valueLines("(defaults)", "octomap", table, OctomapExportOptions{}),
              simp_test::shippedValues("(defaults)", "octomap"));
    const auto o = simp::export3d::loadOctomapExportOptions(simp_test::shippedIni("octomap.ini"));
    const auto expected = simp_test::shippedValues("octomap.ini", "octomap");
    ASSERT_EQ(expected.size(), table.keys().size());
    EXPECT_EQ(simp_test::valueLines("octomap.ini", "octomap", table, o), expected);
}

TEST(OctomapOptionsShipped, DocumentedKeyTableIsTheDeclaration) {
    const std::string table = OctomapExportOptions::table().markdown(OctomapExportOptions{});
    EXPECT_NE(simp_test::docText("import-export.md").find(table), std::string::npos) << "doc/import-export.md should hold:\n"
                                                                                     << table;
}
