#pragma once
/// \file RawlogReader.h
/// Reads a rawlog of 3D-object observations into frames, with errors that name the file
/// and the entry. Both MRPT rawlog formats are accepted:
///  - actions + sensory frames: CActionCollection (odometry increment) then CSensoryFrame;
///  - observations only: CObservationOdometry (absolute odometry) and CObservationObjects3D,
///    grouped into one frame per distinct timestamp.

#include <mrpt/io/CStream.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/system/datetime.h>
#include <simp/obs/CObservationObjects3D.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::obs {

struct RawlogFrame {
    mrpt::system::TTimeStamp timestamp{};                       ///< of the observations (or the action)
    std::optional<mrpt::math::TPose2D> odometry_increment;      ///< motion since the previous frame (robot frame)
    std::vector<CObservationObjects3D::Ptr> observations;       ///< one per camera
};

/// Reads the whole file. Throws std::runtime_error("rawlog 'FILE': entry N: ...") on a missing,
/// truncated or corrupted file, and on an object of a class not in rawlogClasses() (BoundedArchive.h:
/// MRPT's readers of other sensors' observations cannot be guarded nor skipped); 2D range scans,
/// odometry observations and comments are read and not used.
std::vector<RawlogFrame> readRawlog(const std::string& path);

/// The same from a stream that delivers exactly `size_bytes` (uncompressed) bytes; `name` is
/// the file name in messages (e.g. a memory buffer for tests and the fuzz target).
std::vector<RawlogFrame> readRawlog(mrpt::io::CStream& in, std::uint64_t size_bytes, const std::string& name);

}  // namespace simp::obs
