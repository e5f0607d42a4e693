#pragma once
/// \file Tum.h
/// TUM trajectory files: one pose per line, `t x y z qx qy qz qw` (s, m, unit quaternion),
/// '#' starts a comment. Planar poses use z = 0 and a rotation about z.

#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace simp::io {

struct StampedPose2D {
    double t_s = 0;              ///< time (s)
    mrpt::math::TPose2D pose;    ///< x, y (m), phi (rad)
};

/// Reads a TUM file; throws std::runtime_error naming the file and line on malformed input
/// (wrong column count, non-numbers, non-finite values, non-increasing time).
std::vector<StampedPose2D> readTum(const std::string& path);
/// The comment line that starts a TUM file written here (with its newline).
std::string tumHeader();
/// One TUM line (with its newline): t and x, y with 6 decimals, z = 0, the quaternion with 9.
std::string tumLine(const StampedPose2D& pose);
/// Writes a TUM file (creates parent folders); throws naming the file on failure.
void writeTum(const std::string& path, const std::vector<StampedPose2D>& poses);

/// Pose at time t by linear interpolation (angle on the shortest arc); nullopt-like false
/// outside [first, last] time.
bool interpolatePose(const std::vector<StampedPose2D>& traj, double t_s, mrpt::math::TPose2D& out);

}  // namespace simp::io
