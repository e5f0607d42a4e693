// CObjectMap::insertObservation with libs/mapping linked: its BuilderInserter (registered when
// libsimp_mapping.so is loaded) runs ObjectMapBuilder on the detections.
#include "common/ErrorOf.h"
#include "maps/TestMaps.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <simp/io/StrictIni.h>
#include <simp/mapping/BuilderInserter.h>
#include <simp/maps/CObjectMap.h>

#include <sstream>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;
using simp_test::errorOf;

mapping::MappingOptions& mappingOptionsOf(CObjectMap& map) {
    return dynamic_cast<mapping::BuilderInsertionOptions&>(*map.insertionOptions.algorithm).mapping;
}

const mapping::ObjectMapBuilder& builderOf(const CObjectMap& map) {
    return dynamic_cast<const mapping::BuilderInserter&>(*map.inserter()).builder();
}

TEST(CObjectMap, InsertObservationBuildsTheMapWithLibsMapping) {
    // Detections of a table and a cabinet (classes the default mapping filters accept within
    // 1..4.5 m), seen twice from the same pose, into an empty map.
    const auto gt = test::smallMap();
    const TPose2D truth(1.0, 0.5, 0.4);
    const auto o = test::detect(gt, truth, {1, 2}, 0.95f);
    CObjectMap map;
    EXPECT_TRUE(map.insertObservation(o, test::pose3D(truth)));
    EXPECT_TRUE(map.insertObservation(o, test::pose3D(truth)));
    ASSERT_NE(map.inserter(), nullptr);
    map.flushInsertions();  // integrate the local map now (no d_xy / d_theta motion happened)
    // Two detections each: tentative objects (min_confirmed_matches = 3), not yet map content.
    EXPECT_EQ(builderOf(map).map().objects.size(), 2u);
    EXPECT_EQ(map.size(), 0u);
    // Confirmed from two detections in one window on: the same insertions make the map content.
    CObjectMap map2;
    mappingOptionsOf(map2).min_confirmed_matches = 2;
    mappingOptionsOf(map2).min_confirmed_windows = 1;
    EXPECT_TRUE(map2.insertObservation(o, test::pose3D(truth)));
    EXPECT_TRUE(map2.insertObservation(o, test::pose3D(truth)));
    map2.flushInsertions();
    ASSERT_EQ(map2.size(), 2u);
    for (const auto& obj : map2.data().objects) {
        const auto& name = map2.data().class_names.at(static_cast<std::size_t>(obj.class_id));
        const auto& expected = gt.objects[name == "table" ? 1 : 2].box;
        EXPECT_LT((obj.box.center - expected.center).norm(), 1e-6) << name;
        EXPECT_EQ(obj.n_match, 2) << name;
    }
}

TEST(CObjectMap, InsertingIntoALoadedMapKeepsItsObjects) {
    // A ground-truth map (one "detection" per object) updated by detections: its objects are
    // content, not tentative objects of the builder (min_confirmed_matches applies to new ones).
    const auto gt = test::smallMap();
    ASSERT_EQ(gt.objects.size(), 5u);
    CObjectMap map;
    map.setData(gt);
    const TPose2D truth(1.0, 0.5, 0.4);
    const auto o = test::detect(gt, truth, {1, 2}, 0.95f);
    EXPECT_TRUE(map.insertObservation(o, test::pose3D(truth)));
    map.flushInsertions();
    EXPECT_EQ(map.size(), 5u);
}

TEST(CObjectMap, InsertOptionsAreTheMappingOptions) {
    // [<prefix>_insertOpts] reads, checks and prints exactly simp::mapping::MappingOptions.
    const std::string section = "map_semanticObjectMap_00_insertOpts";
    mrpt::config::CConfigFileMemory ini("[" + section + "]\ntau_cost = 0.25\nwall_align = false\n");
    CObjectMap::TInsertionOptions options;
    options.loadFromConfigFile(ini, section);
    mapping::MappingOptions expected;
    expected.loadFromConfigFile(ini, section);
    std::ostringstream dump, expected_dump;
    options.dumpToTextStream(dump);
    expected.dumpToTextStream(expected_dump);
    EXPECT_EQ(dump.str(), "\n----------- [simp::maps::CObjectMap::TInsertionOptions] ------------\n\n" +
                              expected_dump.str());
    // the dump is MappingOptions::table()'s: "key = value  // meaning", readable back as an .ini
    EXPECT_NE(dump.str().find("\ntau_cost                             = 0.25  // "), std::string::npos) << dump.str();
    // A copy is a value.
    CObjectMap::TInsertionOptions copy = options;
    dynamic_cast<mapping::BuilderInsertionOptions&>(*copy.algorithm).mapping.tau_cost = 0.5;
    EXPECT_DOUBLE_EQ(dynamic_cast<mapping::BuilderInsertionOptions&>(*options.algorithm).mapping.tau_cost, 0.25);

    // Bad values name the key, as simp-map's [mapping] does.
    mrpt::config::CConfigFileMemory bad("[" + section + "]\ntau_cost = 5\n");
    const auto msg = errorOf([&] { CObjectMap::TInsertionOptions().loadFromConfigFile(bad, section); });
    EXPECT_NE(msg.find("tau_cost"), std::string::npos) << msg;
    // Read through io::StrictIni (simp-localize's [MetricMap]), its keys are the known ones.
    const io::StrictIni strict("[" + section + "]\ntau_cots = 0.3\n", "a.ini");
    const auto unknown = errorOf([&] {
        strict.loadChecked([&](const io::StrictIni& c) { CObjectMap::TInsertionOptions().loadFromConfigFile(c, section); });
    });
    EXPECT_NE(unknown.find("a.ini: [" + section + "] unknown key 'tau_cots'"), std::string::npos) << unknown;
}

}  // namespace
}  // namespace simp::maps
