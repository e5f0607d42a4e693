// Containers nested anywhere inside one rawlog entry (issue #14). MRPT 2.5 reads an entry's inner
// objects with its own ReadObject: a sensory frame or action collection stored where an
// observation belongs is read whole, sized from its count, before its class is found wrong. The
// guard used to scan 64 KB ahead of each entry, so a header further in went unchecked; now
// BoundedArchive::read() recognises every header MRPT reads, at any depth and offset.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include "RawlogBytes.h"
#include "common/UnderAsan.h"
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/RawlogReader.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

using ::testing::HasSubstr;
using simp_test::Bytes;
using simp_test::bytesOf;
using simp_test::append;
using simp_test::peakRssKb;
using simp_test::readError;

namespace {

void appendU32(Bytes& b, std::uint32_t v) {
    b.resize(b.size() + 4);
    std::memcpy(b.data() + b.size() - 4, &v, 4);
}

/// The header and count of a container as MRPT writes it (CSensoryFrame version 2 or
/// CActionCollection version 0: the u32 count follows the version byte); its elements and the end
/// flag (0x88) are up to the caller.
Bytes containerStart(const std::string& cls, std::uint32_t count) {
    Bytes b(1 + cls.size());
    b[0] = static_cast<std::uint8_t>(0x80 | cls.size());
    std::memcpy(b.data() + 1, cls.data(), cls.size());
    b.push_back(cls.size() >= 13 && cls.compare(cls.size() - 13, 13, "CSensoryFrame") == 0 ? 2 : 0);
    appendU32(b, count);
    return b;
}

/// A comment observation of `n` bytes of text: a valid element that pushes what follows it `n`
/// bytes further into the entry.
Bytes comment(std::size_t n) {
    mrpt::obs::CObservationComment c;
    c.text = std::string(n, 'x');
    c.timestamp = mrpt::Clock::fromDouble(1.0);  // the same bytes every run (saved input)
    return bytesOf(c);
}

/// The valid entry that follows the hostile one.
Bytes validFrame() { return simp_test::oneDetectionFrame(0.5f); }

/// A frame whose first observation is a 100 KB comment and whose second is a sensory frame claiming
/// `count` observations: the nested header lies 100 KB into the entry, beyond the old 64 KB scan.
Bytes frameWithDeepNestedCount(std::uint32_t count) {
    Bytes b = containerStart("mrpt::obs::CSensoryFrame", 2);
    append(b, comment(100000));
    append(b, containerStart("mrpt::obs::CSensoryFrame", count));
    b.push_back(0x88);  // nested frame's end flag (never reached)
    b.push_back(0x88);
    append(b, validFrame());
    return b;
}

}  // namespace

TEST(HostileNesting, AFrameWhereAnObservationBelongsIsRefusedByItsClass) {
    // The same layout with an honest nested count (0): the count passes, but since the thirteenth
    // session the archive reads frames itself and each element must be an observation (MRPT 2.5 kept a
    // nested frame as a null observation).
    EXPECT_THAT(readError(frameWithDeepNestedCount(0)),
                HasSubstr("a 'mrpt::obs::CSensoryFrame' where a mrpt::obs::CObservation belongs"));
}

TEST(HostileNesting, HugeCountNestedBeyond64KBIsRejectedInBoundedMemory) {
    // 40 million observations claimed 100 KB into the entry: MRPT would resize the nested frame's
    // vector to 640 MB (16 bytes each) before finding it is no observation. The saved input
    // tests/data/fuzz_regressions/rawlog/nested-count-100KB-deep.rawlog is this one (also replayed by
    // HostileObservation.SavedFuzzFindingsAreRejectedQuickly).
    const Bytes b = frameWithDeepNestedCount(40000000u);
    ASSERT_GT(b.size(), 100000u);
    const auto saved = std::filesystem::path(SIMP_SOURCE_DIR) /
                       "tests/data/fuzz_regressions/rawlog/nested-count-100KB-deep.rawlog";
    if (std::getenv("SIMP_REGENERATE_FUZZ_REGRESSIONS"))  // to rewrite the saved input after a format change
        std::ofstream(saved, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
    std::ifstream f(saved, std::ios::binary);
    EXPECT_EQ(Bytes(std::istreambuf_iterator<char>(f), {}), b) << saved << " is not the input of this test";
    (void)readError(frameWithDeepNestedCount(0));  // warm-up: MRPT's tables, stream buffers
    [[maybe_unused]] const long base_kb = peakRssKb();
    const auto start = std::chrono::steady_clock::now();
    const std::string err = readError(b);
    EXPECT_THAT(err, HasSubstr("entry 0"));
    EXPECT_THAT(err, HasSubstr("the CSensoryFrame 100"));  // where it lies: 100 0xx bytes in
    EXPECT_THAT(err, HasSubstr("bytes into the entry: element count 40000000 needs at least 120000000 bytes"));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
#if !SIMP_UNDER_ASAN  // ASan's quarantine keeps freed memory resident
    // The input is 100 KB; the read may take a few times that, not the 640 MB MRPT would allocate.
    EXPECT_LT(peakRssKb() - base_kb, 8 * 1024) << "peak RSS grew by " << peakRssKb() - base_kb << " KB";
#endif
}

TEST(HostileNesting, NestedContainersCountTogether) {
    // Two nested frames each claiming 0.6 x the entry's bytes: each fits alone, together they
    // claim the same bytes twice (a valid entry's containers hold distinct objects).
    const std::uint32_t n = 20000;  // 60 000 bytes of elements each, in a ~100 KB entry
    Bytes b = containerStart("mrpt::obs::CSensoryFrame", 2);
    append(b, containerStart("mrpt::obs::CSensoryFrame", n));
    append(b, containerStart("mrpt::obs::CSensoryFrame", n));
    append(b, comment(100000));
    append(b, validFrame());
    // Since the thirteenth session a frame's elements must be observations, so the first nested frame
    // is refused by its class (its count alone fits) before the second one is reached; the sum over an
    // entry's containers stays as a second line for readers that let MRPT read nested objects.
    const std::string err = readError(b);
    EXPECT_THAT(err, HasSubstr("a 'mrpt::obs::CSensoryFrame' where a mrpt::obs::CObservation belongs"));
}

TEST(HostileNesting, AnActionCollectionNestedInAFrameIsCheckedToo) {
    // MRPT reads a collection nested in a frame with its own reader: its count is checked wherever
    // it lies (at most 64 actions).
    Bytes b = containerStart("mrpt::obs::CSensoryFrame", 3);
    append(b, comment(80000));
    append(b, containerStart("x::CActionCollection", 1000));
    b.push_back(0x88);
    append(b, comment(10000));  // bytes enough for the 1000 actions' minimum size
    b.push_back(0x88);
    append(b, validFrame());
    EXPECT_THAT(readError(b), HasSubstr("holds 1000 actions (at most 64"));
}

TEST(HostileNesting, DeepNestingIsAnErrorNotAStackOverflow) {
    // 200 000 frames each holding the next one (19 bytes a level, 3.8 MB): every count fits, but
    // MRPT's readers recurse once per level and would overflow the stack (a segfault).
    const int levels = 200000;
    const Bytes level = containerStart("CSensoryFrame", 1);  // MRPT ignores the namespace
    Bytes b;
    b.reserve(levels * (level.size() + 1) + 200);
    for (int i = 0; i < levels; ++i) append(b, level);
    append(b, validFrame());
    b.insert(b.end(), levels, 0x88);
    // Refused at the first nested level since frames are read by the archive (elements must be
    // observations); the 512 KB stack bound stays for MRPT readers that recurse.
    const auto start = std::chrono::steady_clock::now();
    EXPECT_THAT(readError(b), HasSubstr("a 'CSensoryFrame' where a mrpt::obs::CObservation belongs"));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

TEST(HostileNesting, RangeScanSizesAreCheckedBeforeMrptResizes) {
    // MRPT's CObservation2DRangeScan reader resizes three vectors to the scan size in the file (9
    // bytes a range) and the sensor label to its length before reading them: a 348 KB simulated
    // LiDAR rawlog with a size of 2^26 took 696 MB.
    mrpt::obs::CObservation2DRangeScan scan;
    scan.resizeScanAndAssign(181, 2.0f, true, 0);
    scan.sensorLabel = "LIDAR";
    scan.timestamp = mrpt::Clock::fromDouble(1.0);
    mrpt::obs::CSensoryFrame sf;
    sf.insert(mrpt::obs::CObservation2DRangeScan::Create(scan));
    const Bytes ok = [&] {
        Bytes b = bytesOf(sf);
        append(b, validFrame());
        return b;
    }();
    EXPECT_EQ(readError(ok), "");
    const std::string pose = "mrpt::poses::CPose3D";
    const auto at = std::search(ok.begin(), ok.end(), pose.begin(), pose.end()) - ok.begin();
    const std::size_t n_at = static_cast<std::size_t>(at) + pose.size() + 1 + 96 + 1;
    std::uint32_t n = 0;
    std::memcpy(&n, ok.data() + n_at, 4);
    ASSERT_EQ(n, 181u) << "the scan size is not where MRPT 2.5 writes it";
    (void)readError(ok);  // warm-up
    [[maybe_unused]] const long base_kb = peakRssKb();
    Bytes big = ok;
    const std::uint32_t huge = 1u << 26;
    std::memcpy(big.data() + n_at, &huge, 4);
    EXPECT_THAT(readError(big), HasSubstr("CObservation2DRangeScan 30 bytes into the entry: 67108864 ranges need"));
    Bytes label = ok;
    const std::uint32_t long_label = 0x7fffffffu;
    std::memcpy(label.data() + n_at + 4 + 5 * 181 + 16, &long_label, 4);
    EXPECT_THAT(readError(label), HasSubstr("sensor label of 2147483647 bytes"));
#if !SIMP_UNDER_ASAN
    EXPECT_LT(peakRssKb() - base_kb, 8 * 1024) << "peak RSS grew by " << peakRssKb() - base_kb << " KB";
#endif
}
