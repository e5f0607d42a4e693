/// \file test_options_shipped.cpp
/// [<prefix>_likelihoodOpts] of every shipped .ini (and no .ini) gives the values the hand-written
/// loader gave (tests/data/options/shipped_values.txt); the keys are declared once in table().
#include "common/ShippedOptions.h"

#include <gtest/gtest.h>
#include <simp/maps/CObjectMap.h>
#include <simp/maps/CObjectMapCreationOptions.h>

using simp::maps::CObjectMap;

TEST(LikelihoodOptionsShipped, EveryIniGivesThePinnedValues) {
    const auto& table = CObjectMap::TLikelihoodOptions::table();
    EXPECT_EQ(simp_test::valueLines("(defaults)", "likelihoodOpts", table, CObjectMap::TLikelihoodOptions{}),
              simp_test::shippedValues("(defaults)", "likelihoodOpts"));
    for (const char* name : {"simp.ini", "simp-paper.ini", "pf-localization.ini"}) {
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

TEST(CreationOptionsShipped, EveryIniGivesThePinnedValuesAndTheDocTableIsTheDeclaration) {
    const auto& table = simp::maps::creationOptionsTable();
    std::string report;
    EXPECT_TRUE(simp_test::matchesPinned("(defaults)", table, CObjectMap::TMapDefinition{}, report)) << report;
    for (const char* name : {"simp.ini", "simp-paper.ini"}) {
        const simp::io::StrictIni cfg(simp_test::shippedIni(name));
        CObjectMap::TMapDefinition o;
        table.load(cfg, "MetricMap_semanticObjectMap_00_creationOpts", o);
        EXPECT_TRUE(simp_test::matchesPinned(name, table, o, report)) << report;
    }
    const std::string md = table.markdown(CObjectMap::TMapDefinition{});
    EXPECT_NE(simp_test::docText("object-map.md").find(md), std::string::npos) << "doc/object-map.md should hold:\n" << md;
    // a definition with a bad likelihood key reports it (MRPT's loader must not throw: load_error)
    CObjectMap::TMapDefinition def;
    def.loadFromConfigFile(simp::io::StrictIni("[m_creationOpts]\nmap_file = x.json\n[m_likelihoodOpts]\neta = 2\n", "m.ini"), "m");
    EXPECT_EQ(def.map_file, "x.json");
    EXPECT_EQ(def.load_error, "[m_likelihoodOpts] eta: must be in (0, 1), got 2");
}
