// Memory bound of the rawlog reader on hostile input (issue #14: "a rawlog of N bytes never drives
// peak memory above ~50 MB + O(N)"; doc/fuzzing.md "Peak memory against input size").
// Every 4-byte slot of a small valid rawlog is overwritten in turn with 0xFFFFFFFF, 0x7FFFFFFF and
// 0x00010000 (huge, signed-max and merely large counts/lengths wherever they fall), and every
// variant is read in this process. The peak RSS of the process may grow by at most 64 x the file
// size + 8 MB over its peak after one warm-up read of the valid file. Why these numbers: valid
// rawlogs of 1-100 MB take 5.6-6.0 x their size (measured, doc/fuzzing.md), so 64 x leaves a tenfold
// headroom for the worst layout; 8 MB covers the allocator's arenas and MRPT's lazily built tables.
// An allocation sized by a forged count instead of by the bytes left (the bug class of issue #14:
// 1.7 GB from 922 bytes) exceeds the bound by orders of magnitude.
#include <gtest/gtest.h>
#include "RawlogBytes.h"
#include "common/UnderAsan.h"
#include <mrpt/io/CMemoryStream.h>
#include <simp/obs/ExampleRawlog.h>
#include <simp/obs/RawlogReader.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

using simp_test::peakRssKb;

namespace {

bool readsCleanly(const std::vector<std::uint8_t>& bytes) {
    mrpt::io::CMemoryStream in;
    in.assignMemoryNotOwn(bytes.data(), bytes.size());
    try {
        (void)simp::obs::readRawlog(in, bytes.size(), "hostile.rawlog");
        return true;
    } catch (const std::bad_alloc&) {
        throw;  // a reader must bound its allocations by the input: this is the failure we look for
    } catch (const std::exception&) {
        return false;  // a clean rejection
    }
}

}  // namespace

TEST(ReaderMemory, HostileCountsKeepPeakRssWithinLinearBoundOfFileSize) {
#if SIMP_UNDER_ASAN
    GTEST_SKIP() << "ASan's quarantine keeps freed memory resident: peak RSS then counts every "
                    "allocation of the 11 000 reads, not the live memory this test bounds";
#endif
    const auto path = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "reader_memory" / "small.rawlog";
    std::filesystem::create_directories(path.parent_path());
    simp::obs::ExampleRawlogParams p;
    p.frames = 2;
    p.cameras = 2;
    p.detections = 3;
    simp::obs::writeExampleRawlog(path.string(), p);
    std::ifstream f(path, std::ios::binary);
    const std::vector<std::uint8_t> valid{std::istreambuf_iterator<char>(f), {}};
    ASSERT_GT(valid.size(), 500u);
    ASSERT_LT(valid.size(), 10000u);
    ASSERT_TRUE(readsCleanly(valid));  // warm-up: MRPT's class registry, stream buffers

    const long base_kb = peakRssKb();
    const std::uint32_t forged[] = {0xFFFFFFFFu, 0x7FFFFFFFu, 0x00010000u};
    int rejected = 0, reads = 0;
    for (const std::uint32_t value : forged)
        for (std::size_t at = 0; at + 4 <= valid.size(); ++at) {
            std::vector<std::uint8_t> bytes = valid;
            std::memcpy(bytes.data() + at, &value, 4);
            rejected += readsCleanly(bytes) ? 0 : 1;
            ++reads;
        }
    const long grown_kb = peakRssKb() - base_kb;
    const long bound_kb = static_cast<long>(64 * valid.size() / 1024) + 8 * 1024;
    EXPECT_LE(grown_kb, bound_kb) << "file " << valid.size() << " bytes, " << reads << " hostile reads";
    // The variants must really be hostile: most of them are rejected (not silently read).
    EXPECT_GT(rejected, reads / 2) << rejected << " of " << reads << " rejected";
}
