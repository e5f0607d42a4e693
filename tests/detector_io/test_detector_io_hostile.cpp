// Detector imports on hostile input (issue #14): an empty poses file segfaulted
// simp-import-omni3d / simp-import-ros-detections (front() of an empty list in the error path).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <simp/io/Tum.h>
#include <simp/detector_io/CameraRig.h>
#include <simp/detector_io/DetectionSet.h>
#include <simp/detector_io/Omni3DPredictions.h>

#include <filesystem>
#include <fstream>

using ::testing::HasSubstr;
using namespace simp;

namespace {
const std::string kData = std::string(SIMP_SOURCE_DIR) + "/tests/data/detector_io/";
}

TEST(DetectorImportHostile, EmptyPosesIsAnErrorNotACrash) {
    const auto set = detector_io::readOmni3DPredictions(kData + "predictions.json");
    ASSERT_FALSE(set.images.empty());
    try {
        detector_io::framesFromDetections(set, {}, detector_io::loadCameraRig(kData + "rig.ini"), "predictions.json");
        FAIL() << "accepted without poses";
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(), HasSubstr("predictions.json: image"));
        EXPECT_THAT(e.what(), HasSubstr("no poses"));
    }
}

TEST(DetectorImportHostile, HugeRigImageIsRejected) {
    const auto dir = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "detector_io_hostile";
    std::filesystem::create_directories(dir);
    const auto path = (dir / "rig.ini").string();
    std::ofstream(path) << "[rig]\ncameras = C\n[C]\nx=0\ny=0\nz=1\nyaw_rad=0\nfx=500\nfy=500\ncx=320\ncy=240\n"
                           "width=2000000000\nheight=2000000000\n";
    try {
        detector_io::loadCameraRig(path);
        FAIL() << "accepted";
    } catch (const std::exception& e) {
        EXPECT_THAT(e.what(), HasSubstr("rig.ini"));
        EXPECT_THAT(e.what(), HasSubstr("width/height"));
    }
}
