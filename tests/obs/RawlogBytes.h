/// \file RawlogBytes.h
/// Rawlog bytes for the hostile-input tests: an object serialized as MRPT writes it, and the error
/// that reading a byte string as a rawlog gives (empty when it reads).
#pragma once

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/CSerializable.h>
#include <simp/obs/RawlogReader.h>

#include <cstdint>
#include <exception>
#include <string>
#include <vector>

namespace simp_test {

using Bytes = std::vector<std::uint8_t>;

inline Bytes bytesOf(const mrpt::serialization::CSerializable& o) {
    mrpt::io::CMemoryStream buf;
    auto a = mrpt::serialization::archiveFrom(buf);
    a << o;
    const auto* p = static_cast<const std::uint8_t*>(buf.getRawBufferData());
    return Bytes(p, p + buf.getTotalBytesCount());
}

inline std::string readError(const Bytes& b) {
    mrpt::io::CMemoryStream in;
    in.assignMemoryNotOwn(b.data(), b.size());
    try {
        simp::obs::readRawlog(in, b.size(), "hostile.rawlog");
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

}  // namespace simp_test
