#pragma once
/// \file Omni3DBox.h
/// Conversion between Omni3D / Cube R-CNN box fields and geometry::Box3D (doc/detector-io.md).
///
/// Cube R-CNN (`cubercnn.util.math_util.get_cuboid_verts_faces`) builds a box from
/// `dimensions` = [W, H, L] and `R_cam` with L along the box's local x, H along local y and W
/// along local z. A Box3D has size = extents along its own x, y, z, so the same solid is
/// Box3D{center_cam, size = (L, H, W), R = R_cam}.
/// Omni3D's `bbox3D_cam` corner order v0..v7 is, in Box3D corner numbering (doc/conventions.md):
/// v0 = 0 (-,-,-), v1 = 1 (+,-,-), v2 = 3 (+,+,-), v3 = 2 (-,+,-), v4 = 4 (-,-,+),
/// v5 = 5 (+,-,+), v6 = 7 (+,+,+), v7 = 6 (-,+,+).

#include <simp/geometry/Box3D.h>

#include <array>

namespace simp::detector_io {

/// Box3D corner index of Omni3D vertex v_i.
constexpr std::array<int, 8> kOmni3DCornerToBox3D = {0, 1, 3, 2, 4, 5, 7, 6};

/// The box of Omni3D fields: center_cam (m), dimensions [W, H, L] (m), R_cam (box -> camera).
geometry::Box3D boxFromOmni3D(const Eigen::Vector3d& center_cam, const Eigen::Vector3d& dimensions_whl,
                              const Eigen::Matrix3d& R_cam);
/// Omni3D dimensions [W, H, L] of a box = (size.z, size.y, size.x).
Eigen::Vector3d omni3DDimensions(const geometry::Box3D& box);
/// The 8 corners in Omni3D order v0..v7.
std::array<Eigen::Vector3d, 8> omni3DCorners(const geometry::Box3D& box);

/// The oriented box through 8 corners given in Omni3D order (the authors' ROS detection array):
/// centre = mean of the corners; local x, y, z = mean of the 4 parallel edge vectors
/// (v1-v0, v2-v3, v5-v4, v6-v7), (v3-v0, v2-v1, v7-v4, v6-v5), (v4-v0, v5-v1, v6-v2, v7-v3),
/// made orthonormal by the polar decomposition (closest rotation, SVD); size = extents of the
/// corners along those axes. Exact for the corners of a box.
/// \throw std::invalid_argument when the corners are degenerate (zero extent, mirrored).
geometry::Box3D boxFromOmni3DCorners(const std::array<Eigen::Vector3d, 8>& corners);

}  // namespace simp::detector_io
