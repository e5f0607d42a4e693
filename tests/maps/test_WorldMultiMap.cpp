// A world becomes MRPT's CMultiMetricMap: floor-plan grid + object map, and MRPT's generic
// interface (computeObservationLikelihood over the multi-map) reaches the object map.
#include <gtest/gtest.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/maps/WorldMultiMap.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/world/World.h>

#include <filesystem>

namespace {

simp::world::World smallWorld() {
    simp::world::World w;
    w.floorplan.setSize(0.0, 10.0, 0.0, 6.0, 0.05, 1.0f);  // all free (MRPT cell value = P(free))
    w.objects.class_names = simp::obs::defaultClassNames();
    w.objects.class_noise.assign(w.objects.class_names.size(), std::nullopt);
    simp::model::NoiseModel n;
    n.cov_m2 = Eigen::Vector2d(0.2 * 0.2, 0.2 * 0.2).asDiagonal();
    const int table = w.objects.classId("table"), cabinet = w.objects.classId("cabinet");
    w.objects.class_noise[table] = n;
    w.objects.class_noise[cabinet] = n;
    const std::vector<std::pair<int, Eigen::Vector3d>> objs = {
        {table, {3.0, 2.0, 0.4}}, {cabinet, {7.0, 5.0, 0.9}}, {table, {8.0, 1.5, 0.4}}};
    for (std::size_t i = 0; i < objs.size(); ++i) {
        simp::world::MapObject o;
        o.id = static_cast<std::int64_t>(i);
        o.class_id = objs[i].first;
        o.box = simp::geometry::makeUprightBox(objs[i].second, {1.2, 0.8, 0.8}, 0.3 * static_cast<double>(i));
        w.objects.objects.push_back(o);
    }
    return w;
}

/// The world's objects seen from `robot` by a forward camera, without noise.
simp::obs::CObservationObjects3D::Ptr perfectObservation(const simp::world::World& w, const mrpt::poses::CPose3D& robot) {
    auto o = simp::obs::CObservationObjects3D::Create();
    o->setCameraPose(simp::obs::cameraPoseOnRobot(0.0, 0.0, 0.6, 0.0));
    const mrpt::poses::CPose3D world_T_camera = robot + o->cameraPose();
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = world_T_camera.getRotationMatrix().asEigen();
    T.translation() = Eigen::Vector3d(world_T_camera.x(), world_T_camera.y(), world_T_camera.z());
    for (const auto& m : w.objects.objects) {
        simp::obs::Detection3D d;
        d.class_id = static_cast<std::uint16_t>(m.class_id);
        d.confidence = 0.99f;
        d.box_in_camera = m.box.transformed(T.inverse());
        if (d.box_in_camera.center.z() > 0.5) o->addDetection(d);
    }
    return o;
}

}  // namespace

TEST(WorldMultiMap, HoldsTheFloorPlanAndTheObjectMap) {
    const auto w = smallWorld();
    const auto multi = simp::maps::makeMultiMetricMap(w);
    ASSERT_EQ(multi->maps.size(), 2u);
    const auto grid = multi->mapByClass<mrpt::maps::COccupancyGridMap2D>();
    const auto objects = multi->mapByClass<simp::maps::CObjectMap>();
    ASSERT_TRUE(grid);
    ASSERT_TRUE(objects);
    EXPECT_EQ(grid->getSizeX(), w.floorplan.getSizeX());
    EXPECT_EQ(objects->data().objects.size(), 3u);
}

TEST(WorldMultiMap, MrptLikelihoodThroughTheMultiMapPrefersTheTruePose) {
    const auto w = smallWorld();
    const auto multi = simp::maps::makeMultiMetricMap(w);
    const mrpt::poses::CPose3D truth(1.0, 2.5, 0.0, 0.0, 0.0, 0.0);
    const auto obs = perfectObservation(w, truth);
    ASSERT_GE(obs->size(), 2u);
    const double at_truth = multi->computeObservationLikelihood(*obs, truth);
    const double shifted = multi->computeObservationLikelihood(*obs, mrpt::poses::CPose3D(1.6, 2.5, 0, 0, 0, 0));
    const double turned = multi->computeObservationLikelihood(*obs, mrpt::poses::CPose3D(1.0, 2.5, 0, 0.3, 0, 0));
    EXPECT_GT(at_truth, shifted);
    EXPECT_GT(at_truth, turned);
    // The grid ignores this observation type (neutral 0): the multi-map's value is the object map's.
    const auto objects = multi->mapByClass<simp::maps::CObjectMap>();
    EXPECT_DOUBLE_EQ(at_truth, objects->computeObservationLikelihood(*obs, truth));
}

TEST(WorldMultiMap, ClassWithoutNoiseModelIsAnErrorNamingIt) {
    auto w = smallWorld();
    w.objects.class_noise[w.objects.classId("cabinet")].reset();
    try {
        simp::maps::makeMultiMetricMap(w);
        FAIL() << "a class without a noise model was accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("cabinet"), std::string::npos) << e.what();
    }
}

TEST(WorldMultiMap, MissingWorldDirectoryIsAnErrorNamingIt) {
    try {
        simp::maps::loadMultiMetricMap("/nonexistent/world_dir");
        FAIL();
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/world_dir"), std::string::npos) << e.what();
    }
}
