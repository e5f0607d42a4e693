#include <mrpt/rtti/CObject.h>
#include <simp/obs/ArchiveRead.h>
#include <simp/obs/BoundedArchive.h>
#include <simp/obs/InputLimits.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace simp::obs::archive {
namespace {

[[noreturn]] void reject(const std::string& what, const std::string& why) {
    throw std::invalid_argument(what + ": " + why);
}

std::string numberText(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

/// The bytes left must hold `needed` more bytes (only checkable on a BoundedArchive).
void requireBytes(const mrpt::serialization::CArchive& in, std::uint64_t needed, const std::string& what,
                  const std::string& claim) {
    const auto left = bytesLeftIn(in);
    if (left && needed > *left)
        reject(what, claim + " needs at least " + std::to_string(needed) + " bytes but only " + std::to_string(*left) +
                         " remain in the file (corrupted or truncated)");
}

constexpr std::uint8_t kEndFlag = 0x88;  // MRPT's SERIALIZATION_END_FLAG after every object

}  // namespace

bool readBool(mrpt::serialization::CArchive& in, const std::string& what) {
    const auto b = in.ReadAs<std::uint8_t>();
    if (b > 1) reject(what, "bool byte = " + std::to_string(b) + " (expected 0 or 1)");
    return b == 1;
}

std::uint32_t readCount(mrpt::serialization::CArchive& in, std::size_t min_bytes_each, std::size_t max_count,
                        const std::string& what) {
    const auto n = in.ReadAs<std::uint32_t>();
    if (n > max_count)
        reject(what, "count " + std::to_string(n) + " exceeds the maximum " + std::to_string(max_count));
    requireBytes(in, static_cast<std::uint64_t>(n) * min_bytes_each, what, "count " + std::to_string(n));
    return n;
}

std::string readString(mrpt::serialization::CArchive& in, std::size_t max_length, const std::string& what) {
    const auto n = in.ReadAs<std::uint32_t>();
    if (n > max_length)
        reject(what, "string length " + std::to_string(n) + " exceeds the maximum " + std::to_string(max_length));
    requireBytes(in, n, what, "string length " + std::to_string(n));
    std::string s(n, '\0');
    if (n) in.ReadBuffer(s.data(), n);
    return s;
}

std::vector<std::string> readStringList(mrpt::serialization::CArchive& in, std::size_t max_count,
                                        std::size_t max_length, const std::string& what) {
    const auto n = readCount(in, sizeof(std::uint32_t), max_count, what);
    std::vector<std::string> out;
    out.reserve(n);
    for (std::uint32_t i = 0; i < n; ++i) out.push_back(readString(in, max_length, what + "[" + std::to_string(i) + "]"));
    return out;
}

double readDouble(mrpt::serialization::CArchive& in, double lo, double hi, const std::string& what) {
    const auto v = in.ReadAs<double>();
    if (!std::isfinite(v) || v < lo || v > hi)
        reject(what, "= " + numberText(v) + " must be a finite number in [" + numberText(lo) + ", " + numberText(hi) +
                         "]");
    return v;
}

mrpt::img::TCamera readCamera(mrpt::serialization::CArchive& in, const std::string& what) {
    // Object header as CArchive::WriteObject writes it: (name length | 0x80), name, version.
    const auto len_byte = in.ReadAs<std::uint8_t>();
    if (!(len_byte & 0x80)) reject(what, "not an MRPT object header (pre-0.5.5 format or corrupted)");
    const std::size_t name_len = len_byte & 0x7F;
    std::string name(name_len, '\0');
    if (name_len) in.ReadBuffer(name.data(), name_len);
    if (mrpt::rtti::findRegisteredClass(name) != CLASS_ID(mrpt::img::TCamera))
        reject(what, "expected a TCamera object, found class '" + name + "'");
    const auto version = in.ReadAs<std::uint8_t>();
    if (version < 4 || version > 6)
        reject(what, "TCamera serialization version " + std::to_string(version) + " is not supported (4..6)");
    // Fields of TCamera::serializeFrom (MRPT 2.5), versions 4..6.
    mrpt::img::TCamera K;
    in >> K.focalLengthMeters;
    for (auto& d : K.dist) in >> d;
    double fx, fy, cx, cy;
    in >> fx >> fy >> cx >> cy;
    for (double v : {K.focalLengthMeters, fx, fy, cx, cy})
        if (!std::isfinite(v)) reject(what, "non-finite intrinsic parameter");
    for (double v : K.dist)
        if (!std::isfinite(v)) reject(what, "non-finite distortion parameter");
    K.setIntrinsicParamsFromValues(fx, fy, cx, cy);
    in >> K.nrows >> K.ncols;
    if (K.nrows > limits::kMaxImageSide_px || K.ncols > limits::kMaxImageSide_px)
        reject(what, "image size " + std::to_string(K.ncols) + " x " + std::to_string(K.nrows) +
                         " px exceeds the maximum side " + std::to_string(limits::kMaxImageSide_px));
    if (version >= 5) K.cameraName = readString(in, limits::kMaxNameLength, what + ", cameraName");
    if (version >= 6) {
        const auto model = in.ReadAs<std::uint8_t>();
        if (model > static_cast<std::uint8_t>(mrpt::img::DistortionModel::kannala_brandt))
            reject(what, "distortion model byte = " + std::to_string(model) + " is not a known model");
        K.distortion = static_cast<mrpt::img::DistortionModel>(model);
    }
    if (in.ReadAs<std::uint8_t>() != kEndFlag) reject(what, "TCamera object end flag missing (corrupted)");
    return K;
}

}  // namespace simp::obs::archive
