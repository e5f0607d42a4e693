#pragma once
/// \file Box3D.h
/// An oriented 3D box: the shape of a detection and of a map object.
///
/// Conventions (doc/conventions.md; algorithms in doc/geometry.md):
///  - `center` is the box centre in the frame the box is expressed in (m).
///  - `size` = (W, H, L): extents along the box's own x, y, z axes (m). (Omni3D's
///    `dimensions` put L along x and W along z: see doc/conventions.md.)
///  - `R` rotates box-axis coordinates into the frame: p_frame = center + R * p_box.
///  - Corner i (0..7) = center + R * (sx W/2, sy H/2, sz L/2) with
///    sx = (i & 1) ? +1 : -1, sy = (i & 2) ? +1 : -1, sz = (i & 4) ? +1 : -1.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

namespace simp::geometry {

struct Box3D {
    Eigen::Vector3d center{Eigen::Vector3d::Zero()};  ///< box centre (m)
    Eigen::Vector3d size{Eigen::Vector3d::Ones()};    ///< (W, H, L) along box x, y, z (m)
    Eigen::Matrix3d R{Eigen::Matrix3d::Identity()};   ///< box axes -> frame

    /// The 8 corners, numbered as in the file comment.
    std::array<Eigen::Vector3d, 8> corners() const;

    /// The same box expressed in another frame: T maps this box's frame into it.
    Box3D transformed(const Eigen::Isometry3d& T) const;

    /// Volume (m^3).
    double volume() const { return size.prod(); }

    /// True when every number is finite, the size positive and R a rotation (det +1).
    bool isValid(double rotation_tolerance = 1e-6) const;
};

/// A box standing on the floor, rotated only about the world's vertical axis:
/// size = (extent along yaw direction, extent across, height).
Box3D makeUprightBox(const Eigen::Vector3d& center, const Eigen::Vector3d& size_xyz, double yaw_rad);

/// Re-expresses a box so that its local z axis is the box axis closest to the
/// frame's +z (up) and the axes stay right-handed; the geometric solid is unchanged.
/// Used to compare and average boxes that came from different conventions
/// (camera boxes have H vertical, map boxes have z vertical).
Box3D canonicalizeUpright(const Box3D& box);

/// True when point p (same frame as the box, m) lies inside the closed box.
bool containsPoint(const Box3D& box, const Eigen::Vector3d& p);

/// Yaw (rad) of the box's local x axis projected on the frame's xy plane.
double yawOf(const Box3D& box);

}  // namespace simp::geometry
