#pragma once
/// \file DetectionRawlog.h
/// Writing detection frames as an MRPT rawlog in the actions + sensory-frames format: for every
/// frame a CActionCollection holding a CActionRobotMovement2D (the odometry increment since the
/// previous frame, zero for the first) and then a CSensoryFrame with one CObservationObjects3D
/// per camera. MRPT's tools read the pairs; obs::readRawlog() reads them back.

#include <simp/io/Tum.h>
#include <simp/obs/RawlogReader.h>

#include <string>
#include <vector>

namespace simp::detector_io {

/// Writes `frames` to `path` (uncompressed; creates parent folders).
/// \throw std::runtime_error naming the file when it cannot write.
void writeDetectionRawlog(const std::string& path, const std::vector<obs::RawlogFrame>& frames);

/// The odometry path of a rawlog: increments composed from the identity at the first frame's
/// time (frames without an increment keep the previous pose).
std::vector<io::StampedPose2D> integrateOdometry(const std::vector<obs::RawlogFrame>& frames);

}  // namespace simp::detector_io
