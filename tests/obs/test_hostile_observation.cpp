// Hostile rawlog bytes (issue #14): counts and lengths larger than the file, bool bytes other
// than 0/1, absurd numbers. Every case must fail fast, without allocating what the file claims,
// with a message naming the entry and the field.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include "RawlogBytes.h"
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/obs/BoundedArchive.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/ExampleRawlog.h>
#include <simp/obs/RawlogReader.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

using ::testing::HasSubstr;
using simp::obs::CObservationObjects3D;
using simp_test::Bytes;
using simp_test::bytesOf;
using simp_test::oneDetectionFrame;
using simp_test::readError;

namespace {


std::size_t find(const Bytes& b, const void* needle, std::size_t n) {
    const auto* p = static_cast<const std::uint8_t*>(needle);
    const auto it = std::search(b.begin(), b.end(), p, p + n);
    EXPECT_NE(it, b.end()) << "marker not found";
    return static_cast<std::size_t>(it - b.begin());
}

template <typename T>
void put(Bytes& b, std::size_t at, T v) {
    std::memcpy(b.data() + at, &v, sizeof v);
}

/// Reads `b` as a rawlog from memory; returns the error message ("" when accepted).
std::size_t confidenceAt(const Bytes& b) {
    const float c = 0.3125f;
    return find(b, &c, sizeof c);
}

}  // namespace

TEST(HostileObservation, TheUnmodifiedFrameReads) { EXPECT_EQ(readError(oneDetectionFrame(0.3125f, true)), ""); }

TEST(HostileObservation, HugeDetectionCountFailsFastWithoutAllocating) {
    auto b = oneDetectionFrame();
    // Detection count: the u32 before the class id (u16) that precedes the confidence.
    const std::size_t count_at = confidenceAt(b) - 2 - 4;
    put<std::uint32_t>(b, count_at, 9999);
    const auto t0 = std::chrono::steady_clock::now();
    const auto err = readError(b);
    EXPECT_THAT(err, HasSubstr("hostile.rawlog"));
    EXPECT_THAT(err, HasSubstr("detection count"));
    EXPECT_THAT(err, HasSubstr("remain in the file"));
    put<std::uint32_t>(b, count_at, 1u << 31);
    EXPECT_THAT(readError(b), HasSubstr("count 2147483648 exceeds the maximum"));
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(2));
}

TEST(HostileObservation, HugeLabelLengthIsRejected) {
    auto b = oneDetectionFrame();
    const std::size_t len_at = find(b, "CAM_X", 5) - 4;
    put<std::uint32_t>(b, len_at, 0xFFFFFFF0u);
    const auto err = readError(b);
    EXPECT_THAT(err, HasSubstr("sensorLabel"));
    EXPECT_THAT(err, HasSubstr("string length 4294967280"));
    put<std::uint32_t>(b, len_at, 1000);  // under the maximum, more than the file holds
    EXPECT_THAT(readError(b), HasSubstr("remain in the file"));
}

TEST(HostileObservation, HugeClassListIsRejected) {
    auto b = oneDetectionFrame();
    // The default class list starts with "sink": u32 count, u32 length 4, "sink".
    const std::size_t count_at = find(b, "sink", 4) - 8;
    put<std::uint32_t>(b, count_at, 0x7FFFFFFFu);
    EXPECT_THAT(readError(b), HasSubstr("class_names': count 2147483647 exceeds the maximum"));
    put<std::uint32_t>(b, count_at, 900);
    EXPECT_THAT(readError(b), HasSubstr("class_names"));
}

TEST(HostileObservation, BoolBytesMustBeZeroOrOne) {
    auto b = oneDetectionFrame();
    // Per detection (v1): after the quaternion (4 doubles) come has_box_2d and has_detector_id.
    const std::size_t has_2d_at = confidenceAt(b) + 4 + 10 * 8;
    ASSERT_LE(b[has_2d_at], 1);
    b[has_2d_at] = 7;
    auto err = readError(b);
    EXPECT_THAT(err, HasSubstr("detection #0: field 'has_box_2d': bool byte = 7"));
    b[has_2d_at] = 0;
    b[has_2d_at + 1] = 2;
    EXPECT_THAT(readError(b), HasSubstr("has_detector_id"));
    // has_intrinsics: the byte after the image size, 4 + 4 + 1 + 4 bytes before the class id.
    auto c = oneDetectionFrame();
    const std::size_t has_k_at = confidenceAt(c) - 2 - 4 - 1;
    ASSERT_EQ(c[has_k_at], 0);
    c[has_k_at] = 0x80;
    EXPECT_THAT(readError(c), HasSubstr("has_intrinsics"));
}

TEST(HostileObservation, CameraNameLengthAndDistortionByteAreChecked) {
    auto b = oneDetectionFrame(0.3125f, true);
    const std::size_t name_at = find(b, "camera1", 7);  // TCamera's default cameraName
    put<std::uint32_t>(b, name_at - 4, 0xFFFFFF00u);
    EXPECT_THAT(readError(b), HasSubstr("intrinsics', cameraName: string length"));
    auto c = oneDetectionFrame(0.3125f, true);
    c[name_at + 7] = 9;  // the distortion model byte (TCamera v6)
    EXPECT_THAT(readError(c), HasSubstr("distortion model byte = 9"));
}

TEST(HostileObservation, AbsurdNumbersAreRejected) {
    auto b = oneDetectionFrame();
    const std::size_t conf_at = confidenceAt(b);
    put<float>(b, conf_at, 7.0f);
    EXPECT_THAT(readError(b), HasSubstr("field 'confidence' = 7"));
    b = oneDetectionFrame();
    put<double>(b, conf_at + 4, 1e300);  // centre x
    EXPECT_THAT(readError(b), HasSubstr("field 'center'"));
    b = oneDetectionFrame();
    put<double>(b, conf_at + 4 + 3 * 8, 1e6);  // size W
    EXPECT_THAT(readError(b), HasSubstr("maximum box side"));
    b = oneDetectionFrame();
    put<double>(b, conf_at + 4 + 3 * 8, std::nan(""));
    EXPECT_THAT(readError(b), HasSubstr("field 'size'"));
}

TEST(HostileObservation, MrptContainerCountsAreGuarded) {
    // CSensoryFrame v2: the u32 observation count follows the object header.
    auto b = oneDetectionFrame();
    const std::size_t header = 1 + std::strlen("mrpt::obs::CSensoryFrame") + 1;
    put<std::uint32_t>(b, header, 0xFFFFFFFFu);
    EXPECT_THAT(readError(b), HasSubstr("CSensoryFrame 0 bytes into the entry: element count 4294967295"));
    mrpt::obs::CActionCollection acts;
    auto a = bytesOf(acts);
    const std::size_t aheader = 1 + std::strlen("mrpt::obs::CActionCollection") + 1;
    put<std::uint32_t>(a, aheader, 0x40000000u);
    EXPECT_THAT(readError(a), HasSubstr("CActionCollection 0 bytes into the entry: element count 1073741824"));
}

namespace {

/// An action collection with one odometry increment (MRPT's Gaussian motion model), followed by the
/// frame, as the simulator writes; `model_at` is the offset of the u32 motion-model selection.
Bytes odometryThenFrame(std::size_t& method_at, std::size_t& model_at) {
    mrpt::obs::CActionCollection acts;
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(mrpt::poses::CPose2D(0.05, 0, 0.01), mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
    acts.insert(mv);
    Bytes b = bytesOf(acts);
    const std::string name = "mrpt::obs::CActionRobotMovement2D";
    method_at = find(b, name.data(), name.size()) + name.size() + 1;  // after the version byte
    const std::string pose = "mrpt::poses::CPose2D";
    model_at = find(b, pose.data(), pose.size()) + pose.size() + 1 + 24 + 1;
    const Bytes frame = oneDetectionFrame();
    b.insert(b.end(), frame.begin(), frame.end());
    return b;
}

}  // namespace

TEST(HostileObservation, MrptMotionModelsAreGuarded) {
    // MRPT's CActionRobotMovement2D reader draws a Thrun model's particles, as many as the file
    // says (32 bytes each: 54 GB from a 1.9 KB rawlog), and segfaults when the estimation method
    // is not odometry but no pose PDF follows. The guard rejects both before MRPT reads.
    std::size_t method_at = 0, model_at = 0;
    const Bytes ok = odometryThenFrame(method_at, model_at);
    EXPECT_EQ(readError(ok), "");
    Bytes thrun = ok;
    put<std::uint32_t>(thrun, model_at, 1u);                       // Thrun
    put<std::uint32_t>(thrun, model_at + 4 + 24, 0x64c3883cu);     // 1.7e9 particles
    const auto start = std::chrono::steady_clock::now();
    EXPECT_THAT(readError(thrun), HasSubstr("1690535996 Thrun motion-model particles"));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
    Bytes few = thrun;
    put<std::uint32_t>(few, model_at + 4 + 24, 300u);  // MRPT's default count reads
    EXPECT_EQ(readError(few), "");
    Bytes model = ok;
    put<std::uint32_t>(model, model_at, 0xc8c50000u);
    EXPECT_THAT(readError(model), HasSubstr("motion model 3368353792 is neither 0 (Gaussian) nor 1 (Thrun)"));
    Bytes method = ok;
    put<std::uint32_t>(method, method_at, 0x00800000u);
    EXPECT_THAT(readError(method), HasSubstr("estimation method 8388608"));
    Bytes scan = ok;
    put<std::uint32_t>(scan, method_at, 1u);  // scan matching, but a CPose2D follows
    EXPECT_THAT(readError(scan), HasSubstr("'mrpt::poses::CPose2D' where a pose PDF belongs"));
}

TEST(HostileObservation, MotionModelGuardMatchesClassNamesAsMrptDoes) {
    // MRPT resolves stored class names ignoring the namespace; libFuzzer found "m,pt::obs::
    // CActionRobotMovement2D" drawing 19.7 million Thrun particles past an exact-name guard
    // (tests/data/fuzz_regressions/rawlog/thrun_namespace_19M_particles.rawlog, 831 bytes).
    std::size_t method_at = 0, model_at = 0;
    Bytes thrun = odometryThenFrame(method_at, model_at);
    put<std::uint32_t>(thrun, model_at, 1u);
    put<std::uint32_t>(thrun, model_at + 4 + 24, 19675492u);
    Bytes renamed = thrun;
    renamed[find(renamed, "mrpt::obs::CActionRobotMovement2D", 33) + 1] = ',';
    EXPECT_THAT(readError(renamed), HasSubstr("19675492 Thrun motion-model particles"));
    Bytes pose_renamed = thrun;
    pose_renamed[find(pose_renamed, "mrpt::poses::CPose2D", 20)] = 'x';
    EXPECT_THAT(readError(pose_renamed), HasSubstr("19675492 Thrun motion-model particles"));
    Bytes not_a_pose = thrun;
    not_a_pose[find(not_a_pose, "mrpt::poses::CPose2D", 20) + 19] = 'E';  // "...CPose2E"
    EXPECT_THAT(readError(not_a_pose), HasSubstr("'mrpt::poses::CPose2E' where its odometry CPose2D belongs"));
    Bytes any_model = thrun;  // MRPT takes every non-zero model selection as Thrun
    put<std::uint32_t>(any_model, model_at, 0x04000000u);
    EXPECT_THAT(readError(any_model), HasSubstr("motion model 67108864 is neither 0 (Gaussian) nor 1 (Thrun)"));
}

TEST(HostileObservation, ActionCollectionsAreBoundedAsAWhole) {
    // 64 actions per collection at most, and 100000 Thrun particles for all its movements together.
    std::size_t method_at = 0, model_at = 0;
    Bytes many = odometryThenFrame(method_at, model_at);
    const std::size_t count_at = find(many, "mrpt::obs::CActionCollection", 28) + 28 + 1;
    put<std::uint32_t>(many, count_at, 65u);
    EXPECT_THAT(readError(many), HasSubstr("CActionCollection 0 bytes into the entry holds 65 actions (at most 64"));
    mrpt::obs::CActionCollection acts;
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions opts;
    opts.modelSelection = mrpt::obs::CActionRobotMovement2D::mmThrun;
    opts.thrunModel.nParticlesCount = 60000;  // each allowed alone
    for (int i = 0; i < 2; ++i) {
        mrpt::obs::CActionRobotMovement2D mv;
        mv.computeFromOdometry(mrpt::poses::CPose2D(0.05, 0, 0.01), opts);
        acts.insert(mv);
    }
    Bytes two = bytesOf(acts);
    EXPECT_THAT(readError(two), HasSubstr("the robot movements of one entry ask for 120000 Thrun motion-model particles together"));
}

TEST(HostileObservation, NestedContainersAreCountedBeforeMrptSizesThem) {
    // MRPT reads an entry's inner objects with its own ReadObject and resizes a nested action
    // collection / sensory frame to its count before noticing it is no CAction/CObservation; libFuzzer
    // found a 1 895-byte rawlog asking for 1.9e9 actions that way (fuzz_regressions/rawlog/
    // timeout-nested-actioncollection-1.9G.rawlog), its name stored with a NUL inside its length.
    std::size_t method_at = 0, model_at = 0;
    const Bytes ok = odometryThenFrame(method_at, model_at);
    const auto header = [](const std::string& name, std::size_t declared) {
        Bytes h(1 + declared, 0);  // a NUL ends the name for MRPT, the rest is skipped
        h[0] = static_cast<std::uint8_t>(0x80 | declared);
        std::memcpy(h.data() + 1, name.data(), name.size());
        return h;
    };
    const auto wrapped = [&](const Bytes& inner, std::uint8_t version, std::uint32_t count) {
        Bytes b = header("mrpt::obs::CActionCollection", 28);
        b.push_back(0);  // version
        b.resize(b.size() + 4);
        put<std::uint32_t>(b, b.size() - 4, 1u);
        b.insert(b.end(), inner.begin(), inner.end());
        b.push_back(version);
        b.resize(b.size() + 4);
        put<std::uint32_t>(b, b.size() - 4, count);
        b.insert(b.end(), ok.begin(), ok.end());
        return b;
    };
    // The nested header is checked as MRPT reads it, 34 bytes in (outer header 30, count 4).
    EXPECT_THAT(readError(wrapped(header("mrpt::obs::CActionCollection", 28), 0, 0x7fffffffu)),
                HasSubstr("the CActionCollection 34 bytes into the entry: element count 2147483647"));
    EXPECT_THAT(readError(wrapped(header("mrpt::obs::CActionCollection", 33), 0, 0x7fffffffu)),
                HasSubstr("the CActionCollection 34 bytes into the entry: element count 2147483647"));
    EXPECT_THAT(readError(wrapped(header("mrpt::obs::CActionCollection", 33), 0, 65)),
                HasSubstr("the CActionCollection 34 bytes into the entry holds 65 actions (at most 64"));
    EXPECT_THAT(readError(wrapped(header("x::CSensoryFrame", 16), 2, 1000000u)),
                HasSubstr("the CSensoryFrame 34 bytes into the entry: element count 1000000"));
    const auto saved = std::filesystem::path(SIMP_SOURCE_DIR) /
                       "tests/data/fuzz_regressions/rawlog/timeout-nested-actioncollection-1.9G.rawlog";
    std::ifstream f(saved, std::ios::binary);
    EXPECT_THAT(readError(Bytes{std::istreambuf_iterator<char>(f), {}}),
                HasSubstr("the CActionCollection 34 bytes into the entry: element count 1886547361 needs"));
    EXPECT_EQ(readError(ok), "");  // a valid collection then frame still reads
}

TEST(HostileObservation, SavedFuzzFindingsAreRejectedQuickly) {
    // Every input libFuzzer found (doc/fuzzing.md) is replayed: a clean rejection within seconds.
    const auto dir = std::filesystem::path(SIMP_SOURCE_DIR) / "tests/data/fuzz_regressions/rawlog";
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        std::ifstream f(e.path(), std::ios::binary);
        const Bytes b{std::istreambuf_iterator<char>(f), {}};
        const auto start = std::chrono::steady_clock::now();
        const auto err = readError(b);
        EXPECT_NE(err, "") << e.path();
        std::cout << e.path().filename().string() << ": " << err.substr(0, 300) << "\n";
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0) << e.path();
        ++n;
    }
    EXPECT_GE(n, 1);
}

TEST(HostileObservation, PlainArchivesStillHaveTheFixedMaxima) {
    // Without a BoundedArchive (MRPT's tools through the plugin) the documented maxima hold.
    auto b = oneDetectionFrame();
    put<std::uint32_t>(b, confidenceAt(b) - 6, 1u << 31);
    mrpt::io::CMemoryStream in;
    in.assignMemoryNotOwn(b.data(), b.size());
    auto a = mrpt::serialization::archiveFrom(in);
    try {
        a.ReadObject();
        FAIL() << "accepted";
    } catch (const std::exception& e) {
        EXPECT_THAT(e.what(), HasSubstr("exceeds the maximum"));
    }
}

TEST(ExampleRawlogHostile, ParametersAreBounded) {
    simp::obs::ExampleRawlogParams p;
    p.frames = 0;  // a rawlog the project's reader rejects
    EXPECT_THROW(simp::obs::validateExampleRawlogParams(p), std::invalid_argument);
    p.frames = static_cast<std::size_t>(-1);  // --frames -1 through stoul
    EXPECT_THROW(simp::obs::validateExampleRawlogParams(p), std::invalid_argument);
    p.frames = 1;
    p.detections = static_cast<std::size_t>(-3);
    try {
        simp::obs::validateExampleRawlogParams(p);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_THAT(e.what(), HasSubstr("detections"));
    }
}
