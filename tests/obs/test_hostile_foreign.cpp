// Observations of other sensors in a rawlog (issue #14): MRPT 2.5's readers of its observation classes
// size strings, vectors and images from the file before reading them (a comment text of 2^30 bytes:
// 1.1 GB), and MRPT's format stores no object length, so such an object can be neither guarded in
// general nor skipped unread. The rawlog readers let MRPT read only rawlogClasses() — each with its
// sizes checked before MRPT's reader runs — and refuse any other class from its header, before MRPT
// creates the object, naming the entry and the class (doc/bad-input.md "Other sensors' observations").
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include "RawlogBytes.h"
#include "common/UnderAsan.h"
#include <mrpt/math/CMatrixF.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/rtti/CObject.h>
#include <simp/obs/BoundedArchive.h>

#include <algorithm>
#include <iostream>
#include <cstring>
#include <string>

using ::testing::HasSubstr;
using simp_test::Bytes;
using simp_test::bytesOf;
using simp_test::append;
using simp_test::peakRssKb;
using simp_test::readError;

namespace {

void putU32(Bytes& b, std::size_t at, std::uint32_t v) { std::memcpy(b.data() + at, &v, 4); }

/// Where `text` starts in `b` (the first time from `from` on), or npos.
std::size_t find(const Bytes& b, const std::string& text, std::size_t from = 0) {
    const auto it = std::search(b.begin() + static_cast<std::ptrdiff_t>(from), b.end(), text.begin(), text.end());
    return it == b.end() ? std::string::npos : static_cast<std::size_t>(it - b.begin());
}

/// An object of class `cls` whose every count and length is 2^32-1: its header, version 0, 64 bytes of
/// 0xFF and the end flag. Any MRPT reader would size something to 4 G elements from it.
Bytes hugeCountsObject(const std::string& cls) {
    Bytes b(1 + cls.size());
    b[0] = static_cast<std::uint8_t>(0x80 | cls.size());
    std::memcpy(b.data() + 1, cls.data(), cls.size());
    b.push_back(0);
    b.insert(b.end(), 64, 0xFF);
    b.push_back(0x88);
    return b;
}

/// A valid frame entry, then a frame (CSensoryFrame version 2) holding `obs`.
Bytes validThenFrameWith(const Bytes& obs) {
    Bytes b = simp_test::oneDetectionFrame();
    const std::string sf = "mrpt::obs::CSensoryFrame";
    b.push_back(static_cast<std::uint8_t>(0x80 | sf.size()));
    b.insert(b.end(), sf.begin(), sf.end());
    b.push_back(2);
    b.resize(b.size() + 4);
    putU32(b, b.size() - 4, 1);
    append(b, obs);
    b.push_back(0x88);
    return b;
}

/// Every registered MRPT observation class the readers do not let MRPT read.
std::vector<const mrpt::rtti::TRuntimeClassId*> foreignObservationClasses() {
    const auto& allowed = simp::obs::rawlogClasses();
    std::vector<const mrpt::rtti::TRuntimeClassId*> out;
    for (const auto* id : mrpt::rtti::getAllRegisteredClassesChildrenOf(CLASS_ID(mrpt::obs::CObservation)))
        if (std::find(allowed.begin(), allowed.end(), id) == allowed.end()) out.push_back(id);
    return out;
}

}  // namespace

TEST(ForeignClasses, EveryOtherObservationClassIsRefusedFromItsHeaderInBoundedMemory) {
    const auto foreign = foreignObservationClasses();
    ASSERT_GT(foreign.size(), 20u);  // MRPT 2.5 registers ~40 observation classes
    std::cout << foreign.size() << " observation classes refused\n";
    (void)readError(validThenFrameWith(hugeCountsObject("mrpt::obs::CObservationImage")));  // warm-up
    [[maybe_unused]] const long base_kb = peakRssKb();
    for (const auto* id : foreign) {
        const std::string cls = id->className;
        SCOPED_TRACE(cls);
        const Bytes obj = hugeCountsObject(cls);
        // nested in a frame (the actions + sensory-frames format), entry 1
        const std::string nested = readError(validThenFrameWith(obj));
        EXPECT_THAT(nested, HasSubstr("rawlog 'hostile.rawlog': entry 1: class " + cls + " (30"));
        EXPECT_THAT(nested, HasSubstr("is not read by simp"));
        // as an entry of its own (the observations-only format), entry 1
        Bytes alone = simp_test::oneDetectionFrame();
        append(alone, obj);
        EXPECT_THAT(readError(alone), HasSubstr("entry 1: class " + cls + " (0 bytes into the entry) is not read"));
        // the same with the namespace MRPT ignores when it looks the class up
        Bytes renamed = validThenFrameWith(hugeCountsObject("x::" + cls.substr(cls.rfind("::") + 2)));
        EXPECT_THAT(readError(renamed), HasSubstr("class " + cls + " (")) << "a class found ignoring its namespace";
    }
#if !SIMP_UNDER_ASAN  // ASan's quarantine keeps freed memory resident
    EXPECT_LT(peakRssKb() - base_kb, 8 * 1024) << "peak RSS grew by " << peakRssKb() - base_kb << " KB";
#endif
}

TEST(ForeignClasses, RealObservationsOfOtherSensorsAreRefusedWithAMessageThatSaysWhatToDo) {
    auto imu = mrpt::obs::CObservationIMU::Create();
    auto image = mrpt::obs::CObservationImage::Create();
    auto gps = mrpt::obs::CObservationGPS::Create();
    auto depth = mrpt::obs::CObservation3DRangeScan::Create();
    auto cloud = mrpt::obs::CObservationPointCloud::Create();
    for (const mrpt::obs::CObservation::Ptr& o : std::vector<mrpt::obs::CObservation::Ptr>{imu, image, gps, depth, cloud}) {
        o->sensorLabel = "OTHER";
        const std::string cls = o->GetRuntimeClass()->className;
        SCOPED_TRACE(cls);
        const std::string err = readError(validThenFrameWith(bytesOf(*o)));
        EXPECT_THAT(err, HasSubstr("entry 1: class " + cls + " (30 bytes into the entry) is not read by simp"));
        EXPECT_THAT(err, HasSubstr("cannot be skipped"));
        EXPECT_THAT(err, HasSubstr("simp reads CSensoryFrame, CActionCollection, CActionRobotMovement2D, "
                                   "CObservationObjects3D, CObservation2DRangeScan, CObservationOdometry, "
                                   "CObservationComment"));
        EXPECT_THAT(err, HasSubstr("rawlog-edit --keep-label"));
    }
}

/// A rawlog with every class of rawlogClasses() as the project and MRPT 2.5 write them.
static Bytes everyClassRawlog() {
    Bytes b;
    mrpt::obs::CObservationComment note;  // rawlog-grabber's first entry
    note.text = "[rawlog-grabber config]";
    append(b, bytesOf(note));
    for (int model = 0; model < 2; ++model) {  // Gaussian, then Thrun (100 particles)
        mrpt::obs::CActionCollection acts;
        mrpt::obs::CActionRobotMovement2D mv;
        mrpt::obs::CActionRobotMovement2D::TMotionModelOptions opts;
        if (model == 1) {
            opts.modelSelection = mrpt::obs::CActionRobotMovement2D::mmThrun;
            opts.thrunModel.nParticlesCount = 100;
        }
        mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0.01), opts);
        acts.insert(mv);
        append(b, bytesOf(acts));
        append(b, simp_test::oneDetectionFrame(0.5f, model == 1));  // with a TCamera the second time
    }
    {  // a scan-matching movement (a pose PDF is stored) and a frame of every observation class
        mrpt::obs::CActionCollection acts;
        mrpt::obs::CActionRobotMovement2D mv;
        mv.estimationMethod = mrpt::obs::CActionRobotMovement2D::emScan2DMatching;
        mv.poseChange = mrpt::poses::CPosePDFGaussian::Create(mrpt::poses::CPose2D(0.2, 0, 0));
        acts.insert(mv);
        append(b, bytesOf(acts));
        mrpt::obs::CSensoryFrame sf;
        auto scan = mrpt::obs::CObservation2DRangeScan::Create();
        scan->resizeScanAndAssign(181, 2.0f, true, 0);
        scan->sensorLabel = "LIDAR";
        auto odo = mrpt::obs::CObservationOdometry::Create();
        odo->sensorLabel = "ODOMETRY";
        auto c = mrpt::obs::CObservationComment::Create();
        c->text = "hello";
        for (const mrpt::obs::CObservation::Ptr& o : std::vector<mrpt::obs::CObservation::Ptr>{scan, odo, c}) {
            o->timestamp = mrpt::Clock::fromDouble(3.0);
            sf.insert(o);
        }
        append(b, bytesOf(sf));
        append(b, simp_test::oneDetectionFrame(0.75f));
    }
    mrpt::obs::CObservationOdometry odo;  // the observations-only format's odometry
    odo.timestamp = mrpt::Clock::fromDouble(4.0);
    append(b, bytesOf(odo));
    return b;
}

TEST(ForeignClasses, EveryClassTheReadersUseStillReads) {
    const Bytes b = everyClassRawlog();
    mrpt::io::CMemoryStream in;
    in.assignMemoryNotOwn(b.data(), b.size());
    const auto frames = simp::obs::readRawlog(in, b.size(), "all-classes.rawlog");
    // the third action's frame holds no detections: a frame with its increment alone, then the detections
    ASSERT_EQ(frames.size(), 4u);
    EXPECT_TRUE(frames[0].odometry_increment.has_value());
    EXPECT_TRUE(frames[1].observations.at(0)->intrinsics().has_value());
    EXPECT_TRUE(frames[2].observations.empty());
    EXPECT_NEAR(frames[2].odometry_increment->x, 0.2, 1e-9);
    EXPECT_EQ(frames[3].observations.size(), 1u);
}

TEST(ForeignClasses, SizesInTheClassesMrptReadsAreCheckedBeforeItsReaderRuns) {
    (void)readError(simp_test::oneDetectionFrame());  // warm-up
    [[maybe_unused]] const long base_kb = peakRssKb();
    {  // a comment text of 2^30 bytes (1.1 GB in MRPT's string reader, measured)
        mrpt::obs::CObservationComment c;
        c.text = std::string(1000, 'x');
        Bytes b = validThenFrameWith(bytesOf(c));
        putU32(b, find(b, "CObservationComment") + 19 + 1, 1u << 30);
        EXPECT_THAT(readError(b), HasSubstr("the CObservationComment 30 bytes into the entry: comment text of "
                                            "1073741824 bytes, but only"));
    }
    {  // an odometry observation's sensor label of 2^31-1 bytes
        mrpt::obs::CObservationOdometry o;
        o.sensorLabel = "ODOMETRY";
        Bytes b = validThenFrameWith(bytesOf(o));
        putU32(b, find(b, "ODOMETRY") - 4, 0x7fffffffu);
        EXPECT_THAT(readError(b), HasSubstr("CObservationOdometry 30 bytes into the entry: sensor label of 2147483647"));
    }
    {  // the camera pose of our observation as a CPose3D version 0: a CMatrixF of 65536 x 65536 floats (16 GB)
        Bytes b = simp_test::oneDetectionFrame();
        const std::string pose = "mrpt::poses::CPose3D";
        const std::size_t v = find(b, pose) + pose.size();
        ASSERT_EQ(b[v], 3) << "MRPT 2.5 writes CPose3D version 3";
        mrpt::math::CMatrixF m(2, 2);
        Bytes matrix = bytesOf(m);
        const std::size_t dims = find(matrix, "CMatrixF") + 8 + 1;
        putU32(matrix, dims, 65536);
        putU32(matrix, dims + 4, 65536);
        Bytes patched(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(v));
        patched.push_back(0);
        append(patched, matrix);
        patched.insert(patched.end(), b.begin() + static_cast<std::ptrdiff_t>(v + 1 + 96), b.end());
        EXPECT_THAT(readError(patched), HasSubstr("the CMatrixF"));
        EXPECT_THAT(readError(patched), HasSubstr("a matrix of 65536 x 65536 cells, but only"));
    }
#if !SIMP_UNDER_ASAN
    EXPECT_LT(peakRssKb() - base_kb, 8 * 1024) << "peak RSS grew by " << peakRssKb() - base_kb << " KB";
#endif
}

TEST(ForeignClasses, LayoutsTheChecksDoNotKnowAreRefused) {
    mrpt::obs::CActionCollection acts;
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0), {});
    acts.insert(mv);
    Bytes b = bytesOf(acts);
    append(b, simp_test::oneDetectionFrame());
    Bytes old = b;  // version 3 (MRPT 0.x) carries a particle count at another offset
    old[find(old, "CActionRobotMovement2D") + 22] = 3;
    EXPECT_THAT(readError(old), HasSubstr("version 3 of CActionRobotMovement2D is not read by simp"));

    mrpt::obs::CObservation2DRangeScan scan;
    scan.resizeScanAndAssign(10, 2.0f, true, 0);
    Bytes s = validThenFrameWith(bytesOf(scan));
    s[find(s, "mrpt::poses::CPose3D", find(s, "CObservation2DRangeScan")) + 20] = 1;  // a CPose3D version 1 holds a matrix object: N not located
    EXPECT_THAT(readError(s), HasSubstr("its sensor pose is a CPose3D of version 1"));
    Bytes s5 = validThenFrameWith(bytesOf(scan));
    s5[find(s5, "CObservation2DRangeScan") + 23] = 5;
    EXPECT_THAT(readError(s5), HasSubstr("version 5 of CObservation2DRangeScan is not read by simp"));
}

TEST(ForeignClasses, ANullOrForeignElementOfAFrameIsAnErrorNotACrash) {
    // MRPT 2.5 reads a frame's elements as any object; a version-0 frame then sets each one's time
    // stamp through the pointer (null: a segfault). The archive reads frames itself now.
    const std::string sf = "mrpt::obs::CSensoryFrame";
    Bytes b = simp_test::oneDetectionFrame();
    b.push_back(static_cast<std::uint8_t>(0x80 | sf.size()));
    b.insert(b.end(), sf.begin(), sf.end());
    b.push_back(0);                                   // version 0: ID (u32), time stamp (u64), count
    b.insert(b.end(), {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0});
    b.push_back(0x80 | 7);                            // a "nullptr" object
    for (char ch : std::string("nullptr")) b.push_back(static_cast<std::uint8_t>(ch));
    b.push_back(0x88);
    b.push_back(0x88);
    EXPECT_THAT(readError(b), HasSubstr("a null object where a mrpt::obs::CObservation belongs"));
}

TEST(ForeignClasses, EveryForgedCountInARawlogOfEveryReadClassKeepsMemoryBounded) {
    // As ReaderMemory.HostileCountsKeepPeakRssWithinLinearBoundOfFileSize (same bound, same reasons),
    // on a rawlog holding every class the readers let MRPT read: every 4-byte slot in turn set to a
    // huge, a signed-max and a large value, wherever it falls (counts, lengths, versions, names).
    // Under ASan the reads still run (memory errors in the checks are findings), the RSS bound does not
    // apply: ASan's quarantine keeps freed memory resident (see ReaderMemory).
    const Bytes valid = everyClassRawlog();
    ASSERT_EQ(readError(valid), "");  // warm-up
    [[maybe_unused]] const long base_kb = peakRssKb();
    int rejected = 0, reads = 0;
    for (const std::uint32_t value : {0xFFFFFFFFu, 0x7FFFFFFFu, 0x00010000u})
        for (std::size_t at = 0; at + 4 <= valid.size(); ++at) {
            Bytes bytes = valid;
            putU32(bytes, at, value);
            rejected += readError(bytes).empty() ? 0 : 1;
            ++reads;
        }
#if !SIMP_UNDER_ASAN
    const long grown_kb = peakRssKb() - base_kb;
    EXPECT_LE(grown_kb, static_cast<long>(64 * valid.size() / 1024) + 8 * 1024)
        << "file " << valid.size() << " bytes, " << reads << " hostile reads";
#endif
    // Fewer are rejected than in ReaderMemory's file: a third of this one is payload where any value
    // reads (181 ranges and their validity bytes, doubles of poses and boxes); measured 4254 of 10605.
    EXPECT_GT(rejected, reads / 3) << rejected << " of " << reads << " rejected";
}
