#include "MrptClassGuards.h"

#include <mrpt/img/TCamera.h>
#include <mrpt/math/CMatrixD.h>
#include <mrpt/math/CMatrixF.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>
#include <mrpt/rtti/CObject.h>
#include <simp/obs/InputLimits.h>
#include <simp/obs/CObservationObjects3D.h>

#include <cstring>
#include <optional>
#include <stdexcept>

namespace simp::obs::detail {

namespace {

using limits::kMaxThrunParticles;
/// Bytes a robot movement's motion model spans after its version (method, CPose2D header of <= 121
/// bytes and data, model, six floats, particle count).
constexpr std::size_t kMovementPeekBytes = 4 + 1 + 120 + 1 + 24 + 1 + 4 + 24 + 4 + 8;
/// A nested pose object: header (<= 121 bytes), version, <= 12 doubles, end flag.
constexpr std::size_t kPosePeekBytes = 1 + 120 + 1 + 96 + 1;

[[noreturn]] void reject(const std::string& where, const std::string& what) {
    throw std::invalid_argument(where + ": " + what);
}

std::string shortName(const char* full) {
    const std::string s(full);
    const auto sep = s.rfind("::");
    return sep == std::string::npos ? s : s.substr(sep + 2);
}

/// The object header at `at` (MRPT 2.x: byte 0x80|length, then the name): its name, or nullopt if
/// `at` holds no new-format header within `b`.
std::optional<std::string> objectNameAt(const std::vector<std::uint8_t>& b, std::size_t at) {
    if (at >= b.size() || !(b[at] & 0x80)) return std::nullopt;
    const std::size_t len = b[at] & 0x7f;
    if (len == 0 || at + 1 + len > b.size()) return std::nullopt;
    const auto* c = reinterpret_cast<const char*>(b.data() + at + 1);
    return std::string(c, ::strnlen(c, len));  // MRPT copies the name as a C string
}

/// The position after a pose object of class `cls` (CPose2D versions 0-1, CPose3D versions 2-3: fixed
/// sizes) stored at `at` in `b`, end flag included; nullopt when `b` (the data) ends first. Any other
/// class, version or an old-format header is an error: what follows could not be located.
std::optional<std::size_t> afterPose(const std::vector<std::uint8_t>& b, std::size_t at,
                                     const mrpt::rtti::TRuntimeClassId* cls, const std::string& where,
                                     const std::string& field) {
    if (at >= b.size()) return std::nullopt;
    const auto name = objectNameAt(b, at);
    if (!name) {
        if (!(b[at] & 0x80) || at + 1 + (b[at] & 0x7f) <= b.size())
            reject(where, "no " + shortName(cls->className) + " object header where its " + field +
                              " belongs (an object header older than MRPT 0.5.5, or a corrupted file)");
        return std::nullopt;
    }
    if (mrpt::rtti::findRegisteredClass(*name) != cls)
        reject(where, "holds a '" + *name + "' where its " + field + " " + shortName(cls->className) + " belongs");
    at += 1 + (b[at] & 0x7f);
    if (at >= b.size()) return std::nullopt;
    const std::uint8_t v = b[at];
    std::size_t data = 0;
    if (cls == CLASS_ID(mrpt::poses::CPose2D) && v <= 1) data = v == 0 ? 12 : 24;
    else if (cls == CLASS_ID(mrpt::poses::CPose3D) && (v == 2 || v == 3)) data = v == 2 ? 56 : 96;
    else
        reject(where, "its " + field + " is a " + shortName(cls->className) + " of version " + std::to_string(v) +
                          ", which simp does not read there (CPose2D 0-1, CPose3D 2-3; corrupted or very old file)");
    return at + 1 + data + 1;
}

/// A u32 length at `at` of a string (`unit` empty: `field` of n bytes) or of n `unit` of `elem` bytes
/// each: they must fit in the bytes after it. Returns the length, or nullopt when `b` ends before it.
std::optional<std::uint32_t> sizeFits(const Ahead& a, const std::vector<std::uint8_t>& b, std::size_t at,
                                      std::uint64_t elem, const std::string& where, const std::string& field,
                                      const std::string& unit = "") {
    if (at + 4 > b.size()) return std::nullopt;
    const std::uint32_t n = u32At(b, at);
    const std::uint64_t rest = a.left > at + 4 ? a.left - (at + 4) : 0;
    if (n * elem > rest)
        reject(where, (unit.empty() ? field + " of " + std::to_string(n) + " bytes,"
                                    : std::to_string(n) + " " + unit + " need " + std::to_string(n * elem) + " bytes") +
                          " but only " + std::to_string(rest) + " remain in the file (corrupted or truncated)");
    return n;
}

/// CActionRobotMovement2D, versions 4-7 (MRPT >= 1.0; 0-3 are rejected): u32 estimation method (1: a
/// pose PDF object follows, MRPT's reader segfaults on another class there); for odometry (0) a CPose2D
/// object, u32 model selection (0 Gaussian; MRPT takes any other value as Thrun), six floats, u32 Thrun
/// particle count. Returns the particles MRPT will draw.
std::uint64_t checkRobotMovement2D(const Ahead& a, std::uint32_t version, const std::string& where) {
    if (version < 4 || version > 7)
        reject(where, "version " + std::to_string(version) +
                          " of CActionRobotMovement2D is not read by simp (versions 4-7, MRPT >= 1.0, are; older ones "
                          "can carry unchecked particle counts or a null pose PDF)");
    const auto& b = a.peek(a.version_bytes + kMovementPeekBytes);
    std::size_t at = a.version_bytes;
    if (at + 4 > b.size()) return 0;
    const std::uint32_t method = u32At(b, at);
    at += 4;
    if (method > 1)
        reject(where, "CActionRobotMovement2D estimation method " + std::to_string(method) +
                          " is neither 0 (odometry) nor 1 (scan matching) (corrupted file)");
    if (method == 1) {  // a pose PDF object follows; MRPT 2.5 crashes on any other object there
        const auto name = objectNameAt(b, at);
        if (!name) {
            if (at < b.size() && at + 1 + (b[at] & 0x7f) <= b.size())
                reject(where, "CActionRobotMovement2D: no object where its pose PDF belongs (corrupted file)");
            return 0;
        }
        const auto* id = mrpt::rtti::findRegisteredClass(*name);
        if (id != CLASS_ID(mrpt::poses::CPosePDFGaussian) && id != CLASS_ID(mrpt::poses::CPosePDFGaussianInf))
            reject(where, "CActionRobotMovement2D holds a '" + *name +
                              "' where a pose PDF belongs (simp reads CPosePDFGaussian and CPosePDFGaussianInf there)");
        return 0;
    }
    const auto after = afterPose(b, at, CLASS_ID(mrpt::poses::CPose2D), where + ": CActionRobotMovement2D", "odometry");
    if (!after) return 0;
    at = *after;
    if (at + 4 > b.size()) return 0;
    const std::uint32_t model = u32At(b, at);
    if (model > 1)
        reject(where, "CActionRobotMovement2D motion model " + std::to_string(model) +
                          " is neither 0 (Gaussian) nor 1 (Thrun) (corrupted file)");
    if (model == 0 || at + 4 + 24 + 4 > b.size()) return 0;
    const std::uint32_t particles = u32At(b, at + 4 + 24);
    if (particles > kMaxThrunParticles)
        reject(where, "CActionRobotMovement2D asks for " + std::to_string(particles) +
                          " Thrun motion-model particles (at most " + std::to_string(kMaxThrunParticles) +
                          "; corrupted file)");
    return particles;
}

/// CObservation2DRangeScan, versions 6-7 (MRPT 2.5 writes 7): aperture (f32), rightToLeft (u8),
/// maxRange (f32), sensorPose (a CPose3D object), u32 N, then MRPT resizes three vectors to N (9 bytes
/// each; a 348 KB rawlog with N = 2^26 took 696 MB), N ranges and N validity bytes, stdError (f32),
/// timestamp (u64), beamAperture (f32), sensorLabel (u32 length, resized before it is read).
void checkRangeScan(const Ahead& a, std::uint32_t version, const std::string& where) {
    if (version < 6 || version > 7)
        reject(where, "version " + std::to_string(version) +
                          " of CObservation2DRangeScan is not read by simp (versions 6-7, as MRPT 2 writes; "
                          "rewrite an older rawlog with MRPT 2's rawlog-edit)");
    const std::size_t at = a.version_bytes + 9;
    const auto after = afterPose(a.peek(at + kPosePeekBytes + 4), at, CLASS_ID(mrpt::poses::CPose3D), where,
                                 "sensor pose");
    if (!after) return;
    const auto n = sizeFits(a, a.peek(*after + 4), *after, 5, where, "scan", "ranges");
    if (!n) return;
    const std::size_t label_at = *after + 4 + 5 * std::size_t{*n} + 4 + 8 + 4;
    sizeFits(a, a.peek(label_at + 4), label_at, 1, where, "sensor label");
}

/// CObservationOdometry, versions 0-2: a CPose2D object, then the sensor label (u32 length).
void checkOdometry(const Ahead& a, std::uint32_t version, const std::string& where) {
    if (version > 2) return;  // MRPT rejects the version before reading anything
    const auto after = afterPose(a.peek(a.version_bytes + kPosePeekBytes + 4), a.version_bytes,
                                 CLASS_ID(mrpt::poses::CPose2D), where, "odometry");
    if (after) sizeFits(a, a.peek(*after + 4), *after, 1, where, "sensor label");
}

}  // namespace

std::uint32_t u32At(const std::vector<std::uint8_t>& b, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, b.data() + at, 4);  // little endian, as MRPT writes on x86/arm
    return v;
}

const std::vector<const mrpt::rtti::TRuntimeClassId*>& guardedRawlogClasses() {
    static const std::vector<const mrpt::rtti::TRuntimeClassId*> classes{
        // entries and what the readers use
        CLASS_ID(mrpt::obs::CSensoryFrame), CLASS_ID(mrpt::obs::CActionCollection),
        CLASS_ID(mrpt::obs::CActionRobotMovement2D), CLASS_ID(simp::obs::CObservationObjects3D),
        CLASS_ID(mrpt::obs::CObservation2DRangeScan), CLASS_ID(mrpt::obs::CObservationOdometry),
        CLASS_ID(mrpt::obs::CObservationComment),  // rawlog-grabber starts its rawlogs with one
        // inside them
        CLASS_ID(mrpt::poses::CPose2D), CLASS_ID(mrpt::poses::CPose3D), CLASS_ID(mrpt::poses::CPosePDFGaussian),
        CLASS_ID(mrpt::poses::CPosePDFGaussianInf), CLASS_ID(mrpt::math::CMatrixF), CLASS_ID(mrpt::math::CMatrixD),
        CLASS_ID(mrpt::img::TCamera)};  // read field by field by CObservationObjects3D (ArchiveRead.h)
    return classes;
}

std::string rawlogClassesText() {
    std::string s;
    for (std::size_t i = 0; i < 7; ++i) s += (i ? ", " : "") + shortName(guardedRawlogClasses()[i]->className);
    return s;
}

std::uint64_t checkObject(const mrpt::rtti::TRuntimeClassId* id, const Ahead& a, const std::string& where) {
    const auto& head = a.peek(a.version_bytes);
    if (head.size() < a.version_bytes) return 0;  // cut by the end of the data: MRPT's reader says so
    const std::uint32_t version = a.version_bytes == 4 ? u32At(head, 0) : head[0];
    if (id == CLASS_ID(mrpt::obs::CActionRobotMovement2D)) return checkRobotMovement2D(a, version, where);
    if (id == CLASS_ID(mrpt::obs::CObservation2DRangeScan)) checkRangeScan(a, version, where);
    else if (id == CLASS_ID(mrpt::obs::CObservationOdometry)) checkOdometry(a, version, where);
    else if (id == CLASS_ID(mrpt::obs::CObservationComment) && version == 0)  // text (u32 length), time stamp
        sizeFits(a, a.peek(a.version_bytes + 4), a.version_bytes, 1, where, "comment text");
    else if ((id == CLASS_ID(mrpt::math::CMatrixF) || id == CLASS_ID(mrpt::math::CMatrixD)) && version == 0) {
        // u32 rows, u32 cols, then MRPT sizes the matrix rows x cols before reading it
        const auto& b = a.peek(a.version_bytes + 8);
        if (b.size() < a.version_bytes + 8) return 0;
        const std::uint64_t cells = std::uint64_t{u32At(b, a.version_bytes)} * u32At(b, a.version_bytes + 4);
        const std::uint64_t elem = id == CLASS_ID(mrpt::math::CMatrixF) ? 4 : 8;
        const std::uint64_t rest = a.left > a.version_bytes + 8 ? a.left - (a.version_bytes + 8) : 0;
        if (cells > rest / elem)
            reject(where, "a matrix of " + std::to_string(u32At(b, a.version_bytes)) + " x " +
                              std::to_string(u32At(b, a.version_bytes + 4)) + " cells, but only " + std::to_string(rest) +
                              " bytes remain in the file (corrupted or truncated)");
    }
    return 0;  // poses, pose PDFs, TCamera, our observation: fixed sizes or read by the project's checked code
}

}  // namespace simp::obs::detail
