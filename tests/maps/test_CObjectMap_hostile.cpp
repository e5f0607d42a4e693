// A hostile CObjectMap archive (issue #14): counts larger than the file, bool bytes other than
// 0/1. The reader must fail fast, naming the field, without allocating what the file claims.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/BoundedArchive.h>

#include <chrono>
#include <cstring>

using ::testing::HasSubstr;
using Bytes = std::vector<std::uint8_t>;

namespace {

/// An empty map (default classes, no class noise): its archive ends with 14 noise flags,
/// the u32 object count and MRPT's end flag.
Bytes emptyMapBytes() {
    simp::maps::CObjectMap map;
    mrpt::io::CMemoryStream buf;
    auto a = mrpt::serialization::archiveFrom(buf);
    a << map;
    const auto* p = static_cast<const std::uint8_t*>(buf.getRawBufferData());
    return Bytes(p, p + buf.getTotalBytesCount());
}

std::string readError(const Bytes& b) {
    mrpt::io::CMemoryStream in;
    in.assignMemoryNotOwn(b.data(), b.size());
    simp::obs::BoundedArchive a(in, b.size(), "hostile_map.bin");
    try {
        a.readObjectGuarded();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(CObjectMapHostile, TheUnmodifiedArchiveReads) { EXPECT_EQ(readError(emptyMapBytes()), ""); }

TEST(CObjectMapHostile, HugeObjectCountFailsFast) {
    auto b = emptyMapBytes();
    const std::size_t count_at = b.size() - 1 - 4;
    const auto t0 = std::chrono::steady_clock::now();
    std::uint32_t n = 1u << 31;
    std::memcpy(&b[count_at], &n, 4);
    EXPECT_THAT(readError(b), HasSubstr("CObjectMap archive: object count: count 2147483648 exceeds the maximum"));
    n = 500000;  // under the maximum, far more than the file holds
    std::memcpy(&b[count_at], &n, 4);
    EXPECT_THAT(readError(b), HasSubstr("remain in the file"));
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(2));
}

TEST(CObjectMapHostile, NoiseFlagMustBeABool) {
    auto b = emptyMapBytes();
    const std::size_t flag_at = b.size() - 1 - 4 - 14;  // class_noise[0]'s flag
    ASSERT_EQ(b[flag_at], 0);
    b[flag_at] = 5;
    EXPECT_THAT(readError(b), HasSubstr("class_noise[0]: field 'has_noise': bool byte = 5"));
}

TEST(CObjectMapHostile, BadOptionsKeepTheDefinitionOwned) {
    // Loading bad options no longer throws out of MRPT's loader (which leaked the definition):
    // the error is kept and thrown when the map is created.
    simp::maps::CObjectMap::TMapDefinition def;
    mrpt::config::CConfigFileMemory ini("[m_likelihoodOpts]\nsensor_model=lidar\n");
    EXPECT_NO_THROW(def.loadFromConfigFile(ini, "m"));
    EXPECT_THAT(def.load_error, HasSubstr("lidar"));
}
