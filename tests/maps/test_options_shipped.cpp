/// \file test_options_shipped.cpp
/// [<prefix>_likelihoodOpts] of every shipped .ini (and no .ini) gives the values the hand-written
/// loader gave (tests/data/options/shipped_values.txt); the keys are declared once in table().
#include "common/ShippedOptions.h"

#include <gtest/gtest.h>
#include <simp/maps/CObjectMap.h>

using simp::maps::CObjectMap;

TEST(LikelihoodOptionsShipped, EveryIniGivesThePinnedValues) {
    const auto& table = CObjectMap::TLikelihoodOptions::table();
    EXPECT_EQ(simp_test::valueLines("(defaults)", "likelihoodOpts", table, CObjectMap::TLikelihoodOptions{}),
              simp_test::shippedValues("(defaults)", "likelihoodOpts"));
    for (const char* name : {"simp.ini", "simp-paper.ini", "d.ini", "edt.ini", "o.ini", "pf-localization.ini"}) {
        SCOPED_TRACE(name);
        const simp::io::StrictIni cfg(simp_test::shippedIni(name));
        CObjectMap::TLikelihoodOptions o;
        o.loadFromConfigFile(cfg, "MetricMap_semanticObjectMap_00_likelihoodOpts");
        const auto expected = simp_test::shippedValues(name, "likelihoodOpts");
        ASSERT_FALSE(expected.empty());
        EXPECT_EQ(simp_test::valueLines(name, "likelihoodOpts", table, o), expected);
    }
}

TEST(LikelihoodOptionsShipped, BadValuesNameSectionAndKey) {
    const auto error = [](const std::string& ini) {
        try {
            CObjectMap::TLikelihoodOptions o;
            o.loadFromConfigFile(simp::io::StrictIni("[m_likelihoodOpts]\n" + ini, "m.ini"), "m_likelihoodOpts");
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error("eta = 1\n"), "[m_likelihoodOpts] eta: must be in (0, 1), got 1");
    EXPECT_EQ(error("edt_sigma_m = abc\n"), "[m_likelihoodOpts] edt_sigma_m = 'abc' is not a finite number");
    EXPECT_EQ(error("sensor_model = laser\n"), "[m_likelihoodOpts] sensor_model: unknown sensor model 'laser' (valid: simp, edt, d, o)");
    EXPECT_EQ(error("sensor_model = EDT\n"), "");  // case-insensitive, as before
}

TEST(LikelihoodOptionsShipped, DocumentedKeyTableIsTheDeclaration) {
    const std::string table = CObjectMap::TLikelihoodOptions::table().markdown(CObjectMap::TLikelihoodOptions{});
    EXPECT_NE(simp_test::docText("object-map.md").find(table), std::string::npos) << "doc/object-map.md should hold:\n" << table;
}
