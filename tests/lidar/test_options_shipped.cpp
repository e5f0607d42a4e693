/// \file test_options_shipped.cpp
/// config_ini/icp-poses.ini (and no .ini) gives the values the hand-written loader gave
/// (tests/data/options/shipped_values.txt); the keys are declared once in IcpPosesOptions::table().
#include "common/ShippedOptions.h"

#include <gtest/gtest.h>
#include <simp/lidar/IcpOptions.h>

using simp::lidar::IcpPosesOptions;

TEST(IcpOptionsShipped, EveryIniGivesThePinnedValues) {
    const auto& table = IcpPosesOptions::table();
    EXPECT_EQ(simp_test::valueLines("(defaults)", "ICP", table, IcpPosesOptions{}), simp_test::shippedValues("(defaults)", "ICP"));
    const simp::io::StrictIni cfg(simp_test::shippedIni("icp-poses.ini"));
    IcpPosesOptions o;
    o.loadFromConfig(cfg, "ICP");
    const auto expected = simp_test::shippedValues("icp-poses.ini", "ICP");
    ASSERT_EQ(expected.size(), table.keys().size());
    EXPECT_EQ(simp_test::valueLines("icp-poses.ini", "ICP", table, o), expected);
}

TEST(IcpOptionsShipped, DocumentedKeyTableIsTheDeclaration) {
    const std::string table = IcpPosesOptions::table().markdown(IcpPosesOptions{});
    EXPECT_NE(simp_test::docText("lidar.md").find(table), std::string::npos) << "doc/lidar.md should hold:\n" << table;
}
