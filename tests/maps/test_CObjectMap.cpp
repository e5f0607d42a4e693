// CObjectMap as an MRPT map: serialization, .ini creation, bad input.
#include "common/ErrorOf.h"
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/maps/CObjectMap.h>

#include "TestMaps.h"

#include <filesystem>
#include <fstream>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;
namespace fs = std::filesystem;

std::string outDir() {
    const fs::path d = fs::path(SIMP_TEST_OUTPUT_DIR) / "maps";
    fs::create_directories(d);
    return d.string();
}

using simp_test::errorOf;

TEST(CObjectMap, SerializationRoundTrip) {
    CObjectMap map;
    map.likelihoodOptions.sensor_model = SensorModelType::D;
    map.likelihoodOptions.eta = 0.2;
    map.likelihoodOptions.confidence_thresholds["chair"] = 0.25;
    auto data = test::smallMap();
    data.objects[1].noise = test::noise(0.1, 0.2, 4.0, 0.03, -0.02);
    data.objects[1].n_match = 7;
    data.objects[1].room_id = 3;
    map.setData(data);

    mrpt::io::CMemoryStream buf;
    auto arch = mrpt::serialization::archiveFrom(buf);
    arch << map;
    buf.Seek(0);
    const auto obj = arch.ReadObject();
    const auto copy = std::dynamic_pointer_cast<CObjectMap>(obj);
    ASSERT_TRUE(copy);
    EXPECT_EQ(copy->likelihoodOptions.sensor_model, SensorModelType::D);
    EXPECT_DOUBLE_EQ(copy->likelihoodOptions.eta, 0.2);
    EXPECT_DOUBLE_EQ(copy->likelihoodOptions.thresholdOf("chair"), 0.25);
    ASSERT_EQ(copy->data().objects.size(), data.objects.size());
    EXPECT_EQ(copy->data().class_names, data.class_names);
    for (std::size_t i = 0; i < data.objects.size(); ++i) {
        const auto& a = data.objects[i];
        const auto& b = copy->data().objects[i];
        EXPECT_EQ(a.id, b.id);
        EXPECT_EQ(a.class_id, b.class_id);
        EXPECT_TRUE(a.box.center.isApprox(b.box.center, 1e-12));
        EXPECT_TRUE(a.box.size.isApprox(b.box.size, 1e-12));
        EXPECT_LT((a.box.R - b.box.R).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_EQ(a.n_match, b.n_match);
        EXPECT_EQ(a.room_id, b.room_id);
        EXPECT_EQ(a.noise.has_value(), b.noise.has_value());
    }
    ASSERT_TRUE(copy->data().objects[1].noise);
    EXPECT_DOUBLE_EQ(copy->data().objects[1].noise->exponent_b, 4.0);
    EXPECT_TRUE(copy->data().objects[1].noise->mean_m.isApprox(Eigen::Vector2d(0.03, -0.02)));
    // Same likelihoods, to the precision the boxes come back with (their rotation to 1e-12 above;
    // the centre noise takes each footprint out along the box's axes).
    const auto o = test::detect(data, TPose2D(1, 0.5, 0.4), {0, 1, 2});
    for (const TPose2D p : {TPose2D(1, 0.5, 0.4), TPose2D(1.2, 0.3, 0.5), TPose2D(-3, 2, 2)})
        EXPECT_NEAR(map.computeObservationLikelihood(o, test::pose3D(p)),
                    copy->computeObservationLikelihood(o, test::pose3D(p)), 1e-12);
}

std::string writeMapFile(const world::ObjectMapData& data, const std::string& name) {
    const std::string path = outDir() + "/" + name;
    world::saveObjectMap(data, path);
    return path;
}

std::string iniText(const std::string& map_file, const std::string& likelihood_lines) {
    return "[MetricMap]\n"
           "occupancyGrid_count=1\n"
           "semanticObjectMap_count=1\n"
           "[MetricMap_occupancyGrid_00_creationOpts]\n"
           "min_x=-5\nmax_x=5\nmin_y=-5\nmax_y=5\nresolution=0.1\n"
           "[MetricMap_semanticObjectMap_00_creationOpts]\n"
           "map_file=" + map_file + "\n"
           "[MetricMap_semanticObjectMap_00_likelihoodOpts]\n" + likelihood_lines;
}

TEST(CObjectMap, CreatedFromAnIniWithAnOccupancyGrid) {
    const auto data = test::smallMap();
    const auto path = writeMapFile(data, "ini_map.json");
    mrpt::config::CConfigFileMemory ini(iniText(path,
                                                "sensor_model=o\n"
                                                "eta=0.2\n"
                                                "confidence_thresholds=chair:0.3, potted plant:0.9\n"
                                                "mp_resolution_m=0.1\n"));
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(ini, "MetricMap");
    ASSERT_EQ(inits.size(), 2u);
    mrpt::maps::CMultiMetricMap multi;
    multi.setListOfMaps(inits);
    const auto grid = multi.mapByClass<mrpt::maps::COccupancyGridMap2D>();
    const auto objects = multi.mapByClass<CObjectMap>();
    ASSERT_TRUE(grid);
    ASSERT_TRUE(objects);
    EXPECT_NEAR(grid->getResolution(), 0.1, 1e-6);
    EXPECT_EQ(objects->size(), data.objects.size());
    EXPECT_EQ(objects->likelihoodOptions.sensor_model, SensorModelType::O);
    EXPECT_DOUBLE_EQ(objects->likelihoodOptions.eta, 0.2);
    EXPECT_DOUBLE_EQ(objects->likelihoodOptions.mp_resolution_m, 0.1);
    EXPECT_DOUBLE_EQ(objects->likelihoodOptions.thresholdOf("chair"), 0.3);         // overridden
    EXPECT_DOUBLE_EQ(objects->likelihoodOptions.thresholdOf("potted plant"), 0.9);  // overridden
    EXPECT_DOUBLE_EQ(objects->likelihoodOptions.thresholdOf("door"), 0.5);          // paper default
    std::ostringstream dump;
    inits.dumpToTextStream(dump);
    EXPECT_NE(dump.str().find("sensor_model"), std::string::npos);
    EXPECT_NE(dump.str().find(path), std::string::npos);

    // The multi-map's likelihood includes ours: detections seen from the truth score higher there.
    const TPose2D truth(1, 0.5, 0.4);
    const auto o = test::detect(data, truth, {0, 1, 2});
    EXPECT_TRUE(objects->canComputeObservationLikelihood(o));
    EXPECT_GT(objects->computeObservationLikelihood(o, test::pose3D(truth)),
              objects->computeObservationLikelihood(o, test::pose3D(TPose2D(0, 0, 0))));
}

TEST(CObjectMap, ClassListOverrideKeepsOnlyThoseClasses) {
    const auto path = writeMapFile(test::smallMap(), "ini_classes.json");
    mrpt::config::CConfigFileMemory ini(iniText(path, "") + "\n[MetricMap_semanticObjectMap_00_creationOpts]\n"
                                                            "class_names=door, chair\n");
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(ini, "MetricMap");
    mrpt::maps::CMultiMetricMap multi(inits);
    const auto objects = multi.mapByClass<CObjectMap>();
    ASSERT_TRUE(objects);
    EXPECT_EQ(objects->data().class_names, (std::vector<std::string>{"door", "chair"}));
    EXPECT_EQ(objects->size(), 3u);  // 1 door + 2 chairs
    for (const auto& obj : objects->data().objects) EXPECT_TRUE(obj.class_id == 0 || obj.class_id == 1);
    ASSERT_TRUE(objects->data().class_noise[1]);  // chair's class noise followed the name
}

TEST(CObjectMapBadInput, MissingMapFileIsNamed) {
    const std::string missing = outDir() + "/does_not_exist.json";
    mrpt::config::CConfigFileMemory ini(iniText(missing, ""));
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(ini, "MetricMap");
    const auto msg = errorOf([&] { mrpt::maps::CMultiMetricMap multi(inits); });
    EXPECT_NE(msg.find(missing), std::string::npos) << msg;
    EXPECT_NE(msg.find("map_file"), std::string::npos) << msg;
}

TEST(CObjectMapBadInput, UnknownSensorModelNamesSectionAndKey) {
    mrpt::config::CConfigFileMemory ini(iniText("", "sensor_model=lidar\n"));
    mrpt::maps::TSetOfMetricMapInitializers inits;
    // Loading keeps the error (MRPT 2.5 leaks a definition whose loading throws); creating throws it.
    inits.loadFromConfigFile(ini, "MetricMap");
    const auto msg = errorOf([&] { mrpt::maps::CMultiMetricMap multi(inits); });
    EXPECT_NE(msg.find("MetricMap_semanticObjectMap_00_likelihoodOpts"), std::string::npos) << msg;
    EXPECT_NE(msg.find("sensor_model"), std::string::npos) << msg;
    EXPECT_NE(msg.find("lidar"), std::string::npos) << msg;
}

TEST(CObjectMapBadInput, BadNumbersNameTheKey) {
    for (const std::string& line : std::vector<std::string>{"eta=0\n", "eta=1.5\n", "mp_resolution_m=0\n", "edt_sigma_m=-1\n",
                                    "confidence_thresholds=chair=0.3\n"}) {
        mrpt::config::CConfigFileMemory ini(iniText("", line));
        mrpt::maps::TSetOfMetricMapInitializers inits;
        inits.loadFromConfigFile(ini, "MetricMap");
        const auto msg = errorOf([&] { mrpt::maps::CMultiMetricMap multi(inits); });
        const std::string key = line.substr(0, line.find('='));
        EXPECT_NE(msg.find(key), std::string::npos) << line << " -> " << msg;
    }
}

TEST(CObjectMapBadInput, ClassNotInTheMapOrUnderThresholdIsIgnored) {
    const auto data = test::smallMap();
    CObjectMap map;
    map.setData(data);
    // A sofa detection (the map has no sofa) and a chair under its 0.7 threshold.
    auto o = test::detect(data, TPose2D(0, 0, 0), {0, 0});
    auto dets = o.detections();
    dets[0].class_id = static_cast<std::uint16_t>(obs::classIndexOf(o.classNames(), "sofa"));
    dets[1].confidence = 0.69f;
    o.setDetections(dets);
    EXPECT_FALSE(map.detectionLogLikelihood(o, 0, TPose2D(0, 0, 0)));
    EXPECT_FALSE(map.detectionLogLikelihood(o, 1, TPose2D(0, 0, 0)));
    double sum = 0.25;
    std::size_t used = 0;
    const TPose2D pose(0, 0, 0);
    map.accumulateLogLikelihoods(o, &pose, 1, &sum, used);
    EXPECT_EQ(used, 0u);
    EXPECT_EQ(sum, 0.25);
    EXPECT_EQ(map.computeObservationLikelihood(o, test::pose3D(pose)), 0.0);
    // At exactly the threshold the detection is used (confidence >= threshold).
    dets[1].confidence = 0.7f;
    o.setDetections(dets);
    EXPECT_TRUE(map.detectionLogLikelihood(o, 1, TPose2D(0, 0, 0)));
}

TEST(CObjectMapBadInput, EmptyMapIsNeutral) {
    CObjectMap map;
    EXPECT_TRUE(map.isEmpty());
    const auto o = test::detect(test::smallMap(), TPose2D(0, 0, 0), {0, 1});
    std::vector<TPose2D> poses = {TPose2D(0, 0, 0), TPose2D(3, 1, 2), TPose2D(-100, 5, -1)};
    std::vector<double> sums(poses.size(), -1.0);
    std::size_t used = 0;
    map.accumulateLogLikelihoods(o, poses.data(), poses.size(), sums.data(), used);
    EXPECT_EQ(used, 0u);
    for (const double s : sums) EXPECT_EQ(s, -1.0);
    for (const auto& p : poses) EXPECT_EQ(map.computeObservationLikelihood(o, test::pose3D(p)), 0.0);
    // clear() empties a full map the same way.
    CObjectMap full;
    full.setData(test::smallMap());
    EXPECT_FALSE(full.isEmpty());
    full.clear();
    EXPECT_TRUE(full.isEmpty());
    EXPECT_FALSE(full.detectionLogLikelihood(o, 0, TPose2D(0, 0, 0)));
}

TEST(CObjectMapBadInput, ClassWithoutNoiseModel) {
    auto data = test::smallMap();
    data.class_noise[data.classId("cabinet")].reset();
    CObjectMap map;  // simp model by default
    const auto msg = errorOf([&] { map.setData(data); });
    EXPECT_NE(msg.find("'cabinet'"), std::string::npos) << msg;
    EXPECT_TRUE(map.isEmpty()) << "a failed setData leaves the map unchanged";
    // The baselines that use no noise model accept it.
    map.likelihoodOptions.sensor_model = SensorModelType::O;
    EXPECT_NO_THROW(map.setData(data));
    // Switching back to simp afterwards fails at the next evaluation, naming the class.
    map.likelihoodOptions.sensor_model = SensorModelType::Simp;
    const auto o = test::detect(data, TPose2D(0, 0, 0), {2});
    const auto msg2 = errorOf([&] { map.detectionLogLikelihood(o, 0, TPose2D(0, 0, 0)); });
    EXPECT_NE(msg2.find("'cabinet'"), std::string::npos) << msg2;
    // With skip_classes_without_noise the class is ignored.
    map.likelihoodOptions.skip_classes_without_noise = true;
    EXPECT_FALSE(map.detectionLogLikelihood(o, 0, TPose2D(0, 0, 0)));
}

TEST(CObjectMap, OtherObservationsAreNeutral) {
    CObjectMap map;
    map.setData(test::smallMap());
    mrpt::obs::CObservationOdometry odo;
    EXPECT_FALSE(map.canComputeObservationLikelihood(odo));
    EXPECT_EQ(map.computeObservationLikelihood(odo, mrpt::poses::CPose3D()), 0.0);
    EXPECT_FALSE(map.insertObservation(odo));
    EXPECT_EQ(map.size(), 5u);
}

TEST(CObjectMap, SavesRepresentationAndVisualization) {
    CObjectMap map;
    map.setData(test::smallMap());
    const std::string prefix = outDir() + "/saved";
    map.saveMetricMapRepresentationToFile(prefix);
    ASSERT_TRUE(fs::exists(prefix + "_objects.json"));
    ASSERT_TRUE(fs::exists(prefix + "_summary.txt"));
    const auto back = world::loadObjectMap(prefix + "_objects.json");
    EXPECT_EQ(back.objects.size(), 5u);
    std::ifstream f(prefix + "_summary.txt");
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("chair"), std::string::npos);
    mrpt::opengl::CSetOfObjects scene;
    map.getVisualizationInto(scene);
    EXPECT_EQ(scene.size(), 10u);  // one box + one label per object
    EXPECT_NE(CObjectMap::classColor(0), CObjectMap::classColor(1));
}

}  // namespace
}  // namespace simp::maps
