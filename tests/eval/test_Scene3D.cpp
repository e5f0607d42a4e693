// The .3Dscene of a run: written as SceneViewer3D reads it, loaded back with MRPT, holding one
// labelled box per object, the trajectories and the particles.
#include <gtest/gtest.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CText.h>
#include <simp/eval/Scene3D.h>
#include <simp/geometry/Box3D.h>
#include <simp/obs/Palette.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace simp::eval;

namespace {

struct Counts {
    std::size_t boxes = 0, texts = 0;
};

Counts countPrimitives(const mrpt::opengl::CSetOfObjects& set) {
    Counts c;
    for (const auto& o : set) {
        c.boxes += std::dynamic_pointer_cast<mrpt::opengl::CBox>(o) != nullptr;
        c.texts += std::dynamic_pointer_cast<mrpt::opengl::CText>(o) != nullptr;
    }
    return c;
}

}  // namespace

TEST(Scene3D, WrittenFileLoadsBackWithEveryLayer) {
    mrpt::maps::COccupancyGridMap2D grid;
    grid.setSize(0.0, 8.0, 0.0, 5.0, 0.05, 1.0f);
    simp::world::ObjectMapData objects;
    objects.class_names = {"table", "chair", "potted plant"};
    objects.class_noise.resize(3);
    for (int k = 0; k < 3; ++k) {
        simp::world::MapObject o;
        o.id = 10 + k;
        o.class_id = k;
        o.box = simp::geometry::makeUprightBox({1.0 + 2 * k, 2.0, 0.4}, {0.8, 0.6, 0.8}, 0.2 * k);
        objects.objects.push_back(o);
    }
    MapLayers layers;
    layers.floorplan = &grid;
    layers.objects = &objects;
    for (int k = 0; k < 6; ++k) layers.ground_truth.push_back({1.0 * k, {1.0 + k, 1.0, 0.0}});
    for (int k = 0; k < 4; ++k) layers.estimate.push_back({1.0 * k, {1.0 + k, 1.2, 0.0}});
    for (int k = 0; k < 250; ++k) layers.particles.push_back({0.02 * k, 3.0, 0.0});

    const auto path = (fs::path(SIMP_TEST_OUTPUT_DIR) / "scene3d" / "run.3Dscene").string();
    fs::remove(path);
    saveScene(*buildScene(layers), path);
    ASSERT_TRUE(fs::is_regular_file(path));
    const auto scene = loadScene(path);

    EXPECT_TRUE(scene->getByName(scene_names::kFloorplan));
    const auto objects_set = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(scene->getByName(scene_names::kObjects));
    ASSERT_TRUE(objects_set);
    const Counts c = countPrimitives(*objects_set);
    EXPECT_EQ(c.boxes, 3u);
    EXPECT_EQ(c.texts, 3u);
    std::vector<std::string> labels;
    for (const auto& o : *objects_set)
        if (const auto t = std::dynamic_pointer_cast<mrpt::opengl::CText>(o)) labels.push_back(t->getString());
    EXPECT_EQ(labels, (std::vector<std::string>{"table #10", "chair #11", "potted plant #12"}));
    // boxes in their class colour, by name: chair is class 1 of this world but 10 of the detector's list
    for (const auto& o : *objects_set)
        if (const auto b = std::dynamic_pointer_cast<mrpt::opengl::CBox>(o); b && b->getName() == "chair #11") {
            const auto rgb = simp::obs::classColorRgb("chair");
            EXPECT_EQ(b->getColor_u8().R, rgb[0]);
            EXPECT_EQ(b->getColor_u8().G, rgb[1]);
        }

    const auto gt = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(scene->getByName(scene_names::kGroundTruth));
    const auto est = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(scene->getByName(scene_names::kEstimate));
    ASSERT_TRUE(gt);
    ASSERT_TRUE(est);
    EXPECT_EQ(gt->getLineCount(), 5u);
    EXPECT_EQ(est->getLineCount(), 3u);
    const auto cloud = std::dynamic_pointer_cast<mrpt::opengl::CPointCloud>(scene->getByName(scene_names::kParticles));
    ASSERT_TRUE(cloud);
    EXPECT_EQ(cloud->size(), 250u);
}

TEST(Scene3D, EmptyLayersAreLeftOut) {
    MapLayers layers;  // nothing but the axes
    const auto scene = buildScene(layers);
    EXPECT_FALSE(scene->getByName(scene_names::kFloorplan));
    EXPECT_FALSE(scene->getByName(scene_names::kObjects));
    EXPECT_FALSE(scene->getByName(scene_names::kGroundTruth));
    EXPECT_FALSE(scene->getByName(scene_names::kParticles));
}

TEST(Scene3D, UnreadableFilesThrowNamingThem) {
    const auto dir = fs::path(SIMP_TEST_OUTPUT_DIR) / "scene3d";
    fs::create_directories(dir);
    EXPECT_THROW(loadScene((dir / "missing.3Dscene").string()), std::runtime_error);
    const auto junk = (dir / "junk.3Dscene").string();
    { std::ofstream(junk) << "not a scene"; }
    try {
        loadScene(junk);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("junk.3Dscene"), std::string::npos) << e.what();
    }
}
