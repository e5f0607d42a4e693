/// Tests of the detector file formats and tools (doc/detector-io.md): Omni3D box convention,
/// rig files, Cube R-CNN predictions JSON, the authors' ROS CSV, rawlog round trips, bad input.
#include "common/ErrorOf.h"
#include <gtest/gtest.h>
#include <mrpt/poses/CPose2D.h>
#include <simp/io/Tum.h>
#include <simp/detector_io/CameraRig.h>
#include <simp/detector_io/DetectionRawlog.h>
#include <simp/detector_io/Omni3DBox.h>
#include <simp/detector_io/Omni3DPredictions.h>
#include <simp/detector_io/RosDetectionsCsv.h>
#include <simp/obs/ObjectClasses.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;
using namespace simp;

namespace {

const std::string kData = std::string(SIMP_SOURCE_DIR) + "/tests/data/detector_io/";
const std::string kBin = std::string(SIMP_BINARY_DIR) + "/bin/";

std::string outDir(const std::string& name) {
    const fs::path p = fs::path(SIMP_TEST_OUTPUT_DIR) / "detector_io" / name;
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

int runTool(const std::string& cmd) { return std::system((kBin + cmd + " > /dev/null 2>&1").c_str()); }

using simp_test::errorOf;

geometry::Box3D randomBox(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    geometry::Box3D b;
    b.center = {u(rng), u(rng), 3 + u(rng)};
    b.size = {1.2 + u(rng), 1.1 + u(rng), 1.3 + u(rng)};
    b.R = Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
    return b;
}

void expectSameFrames(const std::vector<obs::RawlogFrame>& a, const std::vector<obs::RawlogFrame>& b, double tol) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].timestamp, b[k].timestamp) << "frame " << k;
        ASSERT_TRUE(a[k].odometry_increment && b[k].odometry_increment);
        EXPECT_NEAR(a[k].odometry_increment->x, b[k].odometry_increment->x, 1e-12);
        EXPECT_NEAR(a[k].odometry_increment->phi, b[k].odometry_increment->phi, 1e-12);
        ASSERT_EQ(a[k].observations.size(), b[k].observations.size());
        for (std::size_t o = 0; o < a[k].observations.size(); ++o) {
            const auto& oa = *a[k].observations[o];
            const auto& ob = *b[k].observations[o];
            EXPECT_EQ(oa.sensorLabel, ob.sensorLabel);
            EXPECT_EQ(oa.classNames(), ob.classNames());
            EXPECT_LT((oa.cameraPose().asVectorVal() - ob.cameraPose().asVectorVal()).norm(), 1e-12);
            ASSERT_EQ(oa.size(), ob.size());
            for (std::size_t i = 0; i < oa.size(); ++i) {
                const auto& da = oa.detections()[i];
                const auto& db = ob.detections()[i];
                EXPECT_EQ(da.class_id, db.class_id);
                EXPECT_EQ(da.confidence, db.confidence);
                EXPECT_LT((da.box_in_camera.center - db.box_in_camera.center).norm(), tol);
                EXPECT_LT((da.box_in_camera.size - db.box_in_camera.size).norm(), tol);
                EXPECT_LT((da.box_in_camera.R - db.box_in_camera.R).norm(), tol);
            }
        }
    }
}

}  // namespace

TEST(Omni3DBox, CornersFollowCubeRcnnConvention) {
    // get_cuboid_verts_faces: x = +-L/2, y = +-H/2, z = +-W/2; v0 = (-,-,-), v1 = (+,-,-),
    // v2 = (+,+,-), v3 = (-,+,-), v4..v7 the same at +z.
    const double W = 0.5, H = 0.9, L = 1.6;
    const auto box = detector_io::boxFromOmni3D({1, 2, 3}, {W, H, L}, Eigen::Matrix3d::Identity());
    const auto v = detector_io::omni3DCorners(box);
    const double sx[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, sy[8] = {-1, -1, 1, 1, -1, -1, 1, 1},
                 sz[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
    for (int i = 0; i < 8; ++i)
        EXPECT_LT((v[static_cast<std::size_t>(i)] - Eigen::Vector3d(1 + sx[i] * L / 2, 2 + sy[i] * H / 2, 3 + sz[i] * W / 2)).norm(),
                  1e-15)
            << "v" << i;
    EXPECT_LT((detector_io::omni3DDimensions(box) - Eigen::Vector3d(W, H, L)).norm(), 1e-15);
}

TEST(Omni3DBox, BoxFromCornersRecoversRandomBoxes) {
    std::mt19937 rng(7);
    for (int k = 0; k < 200; ++k) {
        const auto b = randomBox(rng);
        const auto f = detector_io::boxFromOmni3DCorners(detector_io::omni3DCorners(b));
        EXPECT_LT((f.center - b.center).norm(), 1e-12);
        EXPECT_LT((f.size - b.size).norm(), 1e-12);
        EXPECT_LT((f.R - b.R).norm(), 1e-12);
    }
    std::array<Eigen::Vector3d, 8> flat;
    flat.fill(Eigen::Vector3d::Zero());
    EXPECT_THROW(detector_io::boxFromOmni3DCorners(flat), std::invalid_argument);
}

TEST(CameraRig, IniAndJsonAgree) {
    const auto a = detector_io::loadCameraRig(kData + "rig.ini");
    const auto b = detector_io::loadCameraRig(kData + "rig.json");
    ASSERT_EQ(a.cameras.size(), 2u);
    ASSERT_EQ(b.cameras.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(a.cameras[i].name, b.cameras[i].name);
        EXPECT_LT((a.cameras[i].robotTCamera().asVectorVal() - b.cameras[i].robotTCamera().asVectorVal()).norm(), 1e-12);
        EXPECT_DOUBLE_EQ(a.cameras[i].intrinsics.fx(), 380.07);
        EXPECT_EQ(a.cameras[i].intrinsics.ncols, 640u);
    }
    // CAMERA_1 looks left: its optical axis (z) is the robot's +y.
    const auto R = a.cameras[1].robotTCamera().getRotationMatrix();
    EXPECT_NEAR(R(1, 2), 1.0, 1e-12);
}

TEST(ImportOmni3D, FramesPosesAndBoxes) {
    const auto set = detector_io::readOmni3DPredictions(kData + "predictions.json");
    const auto rig = detector_io::loadCameraRig(kData + "rig.ini");
    const auto poses = io::readTum(kData + "poses.tum");
    const auto frames = detector_io::framesFromDetections(set, poses, rig, "predictions.json");
    ASSERT_EQ(frames.size(), 3u);  // t = 100.5 (two cameras), 101.5, 102.5
    EXPECT_EQ(frames[0].observations.size(), 2u);
    EXPECT_NEAR(frames[0].odometry_increment->x, 0.0, 1e-15);
    // Increment 100.5 -> 101.5 = pose(101.5) (-) pose(100.5) of the linear interpolation.
    mrpt::math::TPose2D p0, p1;
    io::interpolatePose(poses, 100.5, p0);
    io::interpolatePose(poses, 101.5, p1);
    const auto inc = (mrpt::poses::CPose2D(p1) - mrpt::poses::CPose2D(p0)).asTPose();
    EXPECT_NEAR(frames[1].odometry_increment->x, inc.x, 1e-12);
    EXPECT_NEAR(frames[1].odometry_increment->y, inc.y, 1e-12);
    EXPECT_NEAR(frames[1].odometry_increment->phi, inc.phi, 1e-12);
    const auto& o = *frames[0].observations[0];
    EXPECT_EQ(o.sensorLabel, "CAMERA_0");
    ASSERT_EQ(o.size(), 2u);
    EXPECT_EQ(o.classNameOf(o.detections()[0]), "chair");
    EXPECT_EQ(o.classNameOf(frames[0].observations[1]->detections()[0]), "cabinet");  // category_id 9
    // table: dimensions [W, H, L] = [0.8, 0.75, 1.6], L along box x, W along box z.
    EXPECT_LT((o.detections()[1].box_in_camera.size - Eigen::Vector3d(1.6, 0.75, 0.8)).norm(), 1e-15);
    ASSERT_TRUE(o.detections()[0].box_2d.has_value());
    EXPECT_FLOAT_EQ(o.detections()[0].box_2d->x_max, 420.0f);
}

TEST(DetectorTools, RoundTripsAreLossless) {
    const std::string d = outDir("roundtrip");
    ASSERT_EQ(runTool("simp-import-omni3d --predictions " + kData + "predictions.json --poses " + kData +
                      "poses.tum --rig " + kData + "rig.ini --out " + d + "/a.rawlog"),
              0);
    ASSERT_EQ(runTool("simp-export-detections --rawlog " + d + "/a.rawlog --out-csv " + d + "/a.csv --out-json " + d +
                      "/a.json --out-tum " + d + "/a.tum"),
              0);
    ASSERT_EQ(runTool("simp-import-omni3d --predictions " + d + "/a.json --poses " + kData + "poses.tum --rig " + kData +
                      "rig.json --out " + d + "/b.rawlog"),
              0);
    ASSERT_EQ(runTool("simp-import-ros-detections --csv " + d + "/a.csv --poses " + kData + "poses.tum --rig " + kData +
                      "rig.ini --out " + d + "/c.rawlog"),
              0);
    ASSERT_EQ(runTool("simp-export-detections --rawlog " + d + "/b.rawlog --out-csv " + d + "/b.csv --out-json " + d +
                      "/b.json"),
              0);
    const auto a = obs::readRawlog(d + "/a.rawlog");
    // Rawlogs store rotations as unit quaternions, so R_cam -> q -> R_cam may move the last bit;
    // everything else (times, classes, scores, centres, sizes, 2D boxes) survives exactly.
    expectSameFrames(a, obs::readRawlog(d + "/b.rawlog"), 1e-14);  // through the JSON
    expectSameFrames(a, obs::readRawlog(d + "/c.rawlog"), 1e-12);  // through the CSV: box refitted from corners
    EXPECT_EQ(slurp(d + "/a.csv"), slurp(kData + "detections.csv")) << "the committed example is the tool's output";
    // Odometry path: increments composed from the identity at the first frame.
    const auto odom = io::readTum(d + "/a.tum");
    ASSERT_EQ(odom.size(), 3u);
    mrpt::math::TPose2D p0, p2;
    const auto gt = io::readTum(kData + "poses.tum");
    io::interpolatePose(gt, 100.5, p0);
    io::interpolatePose(gt, 102.5, p2);
    const auto rel = (mrpt::poses::CPose2D(p2) - mrpt::poses::CPose2D(p0)).asTPose();
    EXPECT_NEAR(odom[2].pose.x, rel.x, 1e-6);  // TUM text has 6 decimals
    EXPECT_NEAR(odom[2].pose.y, rel.y, 1e-6);
}

TEST(DetectorBadInput, MissingFile) {
    const auto rig = detector_io::loadCameraRig(kData + "rig.ini");
    EXPECT_NE(errorOf([] { detector_io::readOmni3DPredictions("/nonexistent/p.json"); }).find("/nonexistent/p.json: file not found"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { detector_io::readRosDetectionsCsv("/nonexistent/d.csv", obs::defaultClassNames(), rig); })
                  .find("/nonexistent/d.csv: file not found"),
              std::string::npos);
    EXPECT_NE(errorOf([] { detector_io::loadCameraRig("/nonexistent/rig.ini"); }).find("rig.ini: file not found"), std::string::npos);
    EXPECT_NE(runTool("simp-import-omni3d --predictions /nonexistent/p.json --poses " + kData + "poses.tum --rig " +
                      kData + "rig.ini --out /tmp/x.rawlog"),
              0);
}

TEST(DetectorBadInput, WrongColumnCount) {
    const std::string f = outDir("bad_columns") + "/d.csv";
    writeText(f, "# header\n100.5,CAMERA_0\n101.5,CAMERA_0,1,2,3\n");
    const auto rig = detector_io::loadCameraRig(kData + "rig.ini");
    const std::string e = errorOf([&] { detector_io::readRosDetectionsCsv(f, obs::defaultClassNames(), rig); });
    EXPECT_NE(e.find(f + ": line 3: wrong column count 5"), std::string::npos) << e;
}

TEST(DetectorBadInput, NonNumber) {
    const auto rig = detector_io::loadCameraRig(kData + "rig.ini");
    std::string row = slurp(kData + "detections.csv");
    const std::string f = outDir("bad_number") + "/d.csv";
    writeText(f, row.replace(row.find("100.5,CAMERA_0,0,"), 17, "100.5,CAMERA_0,abc,"));
    const std::string e = errorOf([&] { detector_io::readRosDetectionsCsv(f, obs::defaultClassNames(), rig); });
    EXPECT_NE(e.find(f + ": line 2: column 3: expected a finite number, got 'abc'"), std::string::npos) << e;

    const std::string j = outDir("bad_number_json") + "/p.json";
    writeText(j, R"({"predictions": [{"timestamp": 1, "camera": "CAMERA_0", "category": "chair", "score": "high",
                  "center_cam": [0,0,1], "dimensions": [1,1,1], "R_cam": [[1,0,0],[0,1,0],[0,0,1]]}]})");
    const std::string ej = errorOf([&] { detector_io::readOmni3DPredictions(j); });
    EXPECT_NE(ej.find(j + ": predictions[0].score: expected a number"), std::string::npos) << ej;
}

TEST(DetectorBadInput, UnknownClass) {
    const std::string j = outDir("bad_class") + "/p.json";
    writeText(j, R"({"predictions": [{"timestamp": 1, "camera": "CAMERA_0", "category": "unicorn", "score": 0.5,
                  "center_cam": [0,0,1], "dimensions": [1,1,1], "R_cam": [[1,0,0],[0,1,0],[0,0,1]]}]})");
    const std::string e = errorOf([&] { detector_io::readOmni3DPredictions(j); });
    EXPECT_NE(e.find(j + ": predictions[0].category: unknown class 'unicorn'"), std::string::npos) << e;

    const auto rig = detector_io::loadCameraRig(kData + "rig.ini");
    std::string csv = slurp(kData + "detections.csv");
    const std::string f = outDir("bad_class_csv") + "/d.csv";
    writeText(f, csv.replace(csv.find(",0.97000002861022949,3"), 22, ",0.97000002861022949,14"));
    const std::string ec = errorOf([&] { detector_io::readRosDetectionsCsv(f, obs::defaultClassNames(), rig); });
    EXPECT_NE(ec.find(f + ": line 5: column 28: unknown class 14"), std::string::npos) << ec;
}

TEST(DetectorBadInput, MissingKey) {
    const std::string j = outDir("missing_key") + "/p.json";
    writeText(j, R"({"predictions": [{"timestamp": 1, "camera": "CAMERA_0", "category": "chair", "score": 0.5,
                  "center_cam": [0,0,1], "R_cam": [[1,0,0],[0,1,0],[0,0,1]]}]})");
    const std::string e = errorOf([&] { detector_io::readOmni3DPredictions(j); });
    EXPECT_NE(e.find(j + ": predictions[0].dimensions: missing key"), std::string::npos) << e;

    const std::string r = outDir("missing_key_rig") + "/rig.json";
    writeText(r, R"({"cameras": [{"name": "C", "x": 0, "y": 0, "z": 1, "yaw_rad": 0, "fx": 1, "fy": 1, "cx": 1, "cy": 1, "width": 2}]})");
    const std::string er = errorOf([&] { detector_io::loadCameraRig(r); });
    EXPECT_NE(er.find(r + ": cameras[0].height: missing key"), std::string::npos) << er;
}

TEST(DetectorBadInput, BadRotationAndOutsidePoses) {
    const std::string j = outDir("bad_rotation") + "/p.json";
    writeText(j, R"({"predictions": [{"timestamp": 1, "camera": "CAMERA_0", "category": "chair", "score": 0.5,
                  "center_cam": [0,0,1], "dimensions": [1,1,1], "R_cam": [[2,0,0],[0,1,0],[0,0,1]]}]})");
    const std::string e = errorOf([&] { detector_io::readOmni3DPredictions(j); });
    EXPECT_NE(e.find(j + ": predictions[0]"), std::string::npos) << e;
    // Inside the file but outside the poses' time range: names the image and camera.
    const std::string k = outDir("outside_poses") + "/p.json";
    writeText(k, R"({"predictions": [{"timestamp": 50, "camera": "CAMERA_0", "category": "chair", "score": 0.5,
                  "center_cam": [0,0,1], "dimensions": [1,1,1], "R_cam": [[1,0,0],[0,1,0],[0,0,1]]}]})");
    const auto set = detector_io::readOmni3DPredictions(k);
    const std::string eo = errorOf([&] {
        detector_io::framesFromDetections(set, io::readTum(kData + "poses.tum"), detector_io::loadCameraRig(kData + "rig.ini"), k);
    });
    EXPECT_NE(eo.find("image 0 (camera 'CAMERA_0', t=50"), std::string::npos) << eo;
    EXPECT_NE(eo.find("outside the poses' range"), std::string::npos) << eo;
}
