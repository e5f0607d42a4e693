/// \file RawlogBytes.h
/// Rawlog bytes for the hostile-input tests: an object serialized as MRPT writes it, a valid frame, and the error
/// that reading a byte string as a rawlog gives (empty when it reads); the process's peak RSS.
#pragma once

#include <mrpt/img/TCamera.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/CSerializable.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/RawlogReader.h>
#include <sys/resource.h>

#include <cstdint>
#include <exception>
#include <string>
#include <vector>

namespace simp_test {

using Bytes = std::vector<std::uint8_t>;

inline void append(Bytes& b, const Bytes& more) { b.insert(b.end(), more.begin(), more.end()); }

/// Peak resident set size of this process so far, in KB (Linux).
inline long peakRssKb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

inline Bytes bytesOf(const mrpt::serialization::CSerializable& o) {
    mrpt::io::CMemoryStream buf;
    auto a = mrpt::serialization::archiveFrom(buf);
    a << o;
    const auto* p = static_cast<const std::uint8_t*>(buf.getRawBufferData());
    return Bytes(p, p + buf.getTotalBytesCount());
}

/// A sensory frame with one 3D-object observation (label "CAM_X", time 1 s: the same bytes every run)
/// holding one detection of the given confidence (0.3125 is exact in float and found by its bytes).
inline Bytes oneDetectionFrame(float confidence = 0.3125f, bool with_intrinsics = false) {
    auto o = simp::obs::CObservationObjects3D::Create();
    o->sensorLabel = "CAM_X";
    o->timestamp = mrpt::Clock::fromDouble(1.0);
    if (with_intrinsics) {
        mrpt::img::TCamera K;
        K.setIntrinsicParamsFromValues(380, 380, 320, 240);
        o->setIntrinsics(K);
    }
    simp::obs::Detection3D d;
    d.class_id = 1;
    d.confidence = confidence;
    d.box_in_camera.center = {0.5, 0.25, 3.0};
    d.box_in_camera.size = {1.0, 0.75, 0.5};
    o->addDetection(d);
    mrpt::obs::CSensoryFrame sf;
    sf.insert(o);
    return bytesOf(sf);
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
