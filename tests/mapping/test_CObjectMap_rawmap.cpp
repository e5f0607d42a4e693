// What RawLogViewer 2.5.8's "map from odometry" dialog (CFormRawMap.cpp) does with the plugins
// (RawLogViewer -l libsimp_mapping.so): a CMultiMetricMap from the dialog's [map] text, sensory
// frames inserted at their poses (insertObservationsInto), theMap.getVisualization() drawn.
#include "maps/TestMaps.h"

#include <simp/maps/CObjectMap.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CText.h>

using namespace simp::maps;

namespace {

/// CBoxes / CTexts anywhere below `set`.
void count(const mrpt::opengl::CSetOfObjects& set, std::size_t& boxes, std::size_t& texts) {
    for (const auto& o : set) {
        boxes += std::dynamic_pointer_cast<mrpt::opengl::CBox>(o) != nullptr;
        texts += std::dynamic_pointer_cast<mrpt::opengl::CText>(o) != nullptr;
        if (const auto sub = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(o)) count(*sub, boxes, texts);
    }
}

}  // namespace

TEST(CObjectMap, RawLogViewersRawMapDialogDrawsTheBuiltBoxes) {
    // The dialog's [map] text with a semanticObjectMap added (confirmation relaxed so that two
    // frames from one pose make content).
    mrpt::config::CConfigFileMemory ini(
        "[map]\n"
        "semanticObjectMap_count=1\n"
        "[map_semanticObjectMap_00_insertOpts]\n"
        "min_confirmed_matches=2\n"
        "min_confirmed_windows=1\n");
    mrpt::maps::TSetOfMetricMapInitializers maps;
    maps.loadFromConfigFile(ini, "map");
    mrpt::maps::CMultiMetricMap the_map;
    the_map.setListOfMaps(maps);
    const auto object_map = the_map.mapByClass<CObjectMap>();
    ASSERT_TRUE(object_map);

    const auto gt = simp::maps::test::smallMap();
    const mrpt::math::TPose2D truth(1.0, 0.5, 0.4);
    mrpt::obs::CSensoryFrame sf;
    sf.insert(std::make_shared<simp::obs::CObservationObjects3D>(simp::maps::test::detect(gt, truth, {1, 2}, 0.95f)));
    for (int k = 0; k < 2; ++k) sf.insertObservationsInto(the_map, simp::maps::test::pose3D(truth));
    object_map->flushInsertions();  // the dialog's odometry moves the robot, which integrates as it goes
    ASSERT_EQ(object_map->size(), 2u);

    std::size_t boxes = 0, texts = 0;
    count(*the_map.getVisualization(), boxes, texts);
    EXPECT_EQ(boxes, 2u);
    EXPECT_EQ(texts, 2u);
}
