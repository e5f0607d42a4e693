// libs/maps alone (test_maps links no libs/mapping): CObjectMap::insertObservation has no map
// construction until libsimp_mapping.so is loaded, as MRPT's tools load plugins. Loading it lasts
// for the process, so each test first checks that it is not loaded yet.
#include "TestMaps.h"
#include "common/ErrorOf.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/system/os.h>
#include <simp/maps/CObjectMap.h>
#include <simp/maps/ObjectMapInserter.h>

#include <sstream>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;
using simp_test::errorOf;

TEST(CObjectMapWithoutMapping, InsertObservationNamesTheLibraryToLoad) {
    if (objectMapInserterFactory())  // a plugin stays loaded: ctest runs each test in its own process
        GTEST_SKIP() << "libsimp_mapping.so was loaded by an earlier test of this process";
    CObjectMap map;
    map.setData(test::smallMap());
    const TPose2D truth(1.0, 0.5, 0.4);
    const auto o = test::detect(test::smallMap(), truth, {1, 2}, 0.95f);
    const auto msg = errorOf([&] { map.insertObservation(o, test::pose3D(truth)); });
    EXPECT_NE(msg.find("libsimp_mapping.so"), std::string::npos) << msg;
    EXPECT_EQ(map.size(), 5u);
    EXPECT_EQ(map.inserter(), nullptr);
    map.flushInsertions();  // nothing to flush
    // The likelihood needs no mapping.
    EXPECT_TRUE(std::isfinite(map.computeObservationLikelihood(o, test::pose3D(truth))));
}

TEST(CObjectMapWithoutMapping, InsertOptionsAreKeptUntilLibsimpMappingIsLoaded) {
    if (objectMapInserterFactory())  // a plugin stays loaded: ctest runs each test in its own process
        GTEST_SKIP() << "libsimp_mapping.so was loaded by an earlier test of this process";
    // RawLogViewer's "map from odometry" [map] text (tests/mapping/test_CObjectMap_rawmap.cpp), read
    // before the mapping library is loaded: the map is made, its insertion options kept as text.
    mrpt::config::CConfigFileMemory ini(
        "[map]\n"
        "semanticObjectMap_count=1\n"
        "[map_semanticObjectMap_00_insertOpts]\n"
        "min_confirmed_matches=2\n"
        "min_confirmed_windows=1\n");
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(ini, "map");
    std::ostringstream dump;
    inits.dumpToTextStream(dump);
    EXPECT_NE(dump.str().find("min_confirmed_matches = 2"), std::string::npos) << dump.str();
    mrpt::maps::CMultiMetricMap multi(inits);
    const auto map = multi.mapByClass<CObjectMap>();
    ASSERT_TRUE(map);
    const TPose2D truth(1.0, 0.5, 0.4);
    const auto o = test::detect(test::smallMap(), truth, {1, 2}, 0.95f);
    EXPECT_NE(errorOf([&] { map->insertObservation(o, test::pose3D(truth)); }).find("libsimp_mapping.so"),
              std::string::npos);

    // Loaded as RawLogViewer -l / rawlog-edit --plugins do: insertion works, with the kept keys.
    std::string load_error;
    ASSERT_TRUE(mrpt::system::loadPluginModule(std::string(SIMP_BINARY_DIR) + "/lib/libsimp_mapping.so", load_error))
        << load_error;
    ASSERT_NE(objectMapInserterFactory(), nullptr);
    EXPECT_TRUE(map->insertObservation(o, test::pose3D(truth)));
    EXPECT_TRUE(map->insertObservation(o, test::pose3D(truth)));
    map->flushInsertions();
    EXPECT_EQ(map->size(), 2u) << "confirmed from 2 detections in 1 window: the kept keys were applied";

    // A kept key the mapping options do not know is an error when they are read.
    CObjectMap other;
    other.insertionOptions.algorithm.reset();
    other.insertionOptions.kept_section = "map_semanticObjectMap_00_insertOpts";
    other.insertionOptions.kept_keys = {{"tau_cots", "0.3"}};
    const auto msg = errorOf([&] { other.insertObservation(o, test::pose3D(truth)); });
    EXPECT_NE(msg.find("unknown key 'tau_cots'"), std::string::npos) << msg;
}

}  // namespace
}  // namespace simp::maps
