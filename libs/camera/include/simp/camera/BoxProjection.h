#pragma once
/// \file BoxProjection.h
/// Projection of a 3D box into a camera (Eq. reprojection, x = K [R t] X with [R t] =
/// camera_T_world, skew included), clipped by the near plane, and its truncation.

#include <simp/geometry/Box3D.h>
#include <simp/camera/PinholeCamera.h>

#include <Eigen/Core>

namespace simp::camera {

/// Axis-aligned image box [x_min, y_min, x_max, y_max] (px).
using ImageBox = Eigen::Vector4d;

/// Area of an image box (0 when empty).
double area(const ImageBox& b);
/// IoU of two image boxes, [0, 1].
double iou2D(const ImageBox& a, const ImageBox& b);

struct ProjectedBox {
    bool visible_in_front = false;  ///< some part of the box lies in front of the near plane
    ImageBox bbox_proj{ImageBox::Zero()};   ///< bounding box of the projected (near-clipped) solid, unclipped to the image
    ImageBox bbox_trunc{ImageBox::Zero()};  ///< bbox_proj clipped to the image [0, width] x [0, height]
    double truncation = 1.0;        ///< 1 - area(bbox_trunc) / area(bbox_proj): the fraction outside the image
};

/// Eq. reprojection for one point: pixel of the world point X (requires z_camera > 0).
Eigen::Vector2d projectPoint(const PinholeCamera& camera, const Eigen::Vector3d& X_world);

/// Projects `box_world`. The solid is first clipped by the plane z_camera = near_m (its 8 corners
/// in front plus the crossings of its 12 edges), so boxes around or behind the camera project
/// correctly; a box entirely behind gives visible_in_front = false and truncation = 1.
ProjectedBox projectBox(const PinholeCamera& camera, const geometry::Box3D& box_world, double near_m = 0.05);

}  // namespace simp::camera
