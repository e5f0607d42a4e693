#pragma once
/// \file PreparedDetection.h
/// A detection made ready, once per observation, to be scored at many particle poses: what every
/// 3D-object sensor model shares (SimpSensorModel, CentreSensorModel, OverlapSensorModel,
/// EdtSensorModel).

#include <simp/geometry/Box3D.h>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/geometry/OrientedRect.h>

#include <Eigen/Core>

namespace simp::maps {

/// A detection, in the robot frame, ready to be moved to many particle poses.
struct PreparedDetection {
    int map_class = -1;                                       ///< class id in the object map
    Eigen::Vector2d center_robot_m{Eigen::Vector2d::Zero()};  ///< box centre on the ground (robot frame, m)
    geometry::ConvexPolygon footprint_robot;                  ///< ground footprint (robot frame, m)
    double area_m2 = 0;                                       ///< footprint area (m^2)
    double radius_m = 0;                                      ///< bounding circle about center_robot_m (m)
    geometry::ConvexPolygon offsets_robot;  ///< footprint_robot - center_robot_m: moved into a map object's frame
    bool is_rect = false;                   ///< footprint_robot is a rectangle: rect_robot (separating-axis test)
    geometry::OrientedRect rect_robot;
    double noise_inv_scale2 = 1;  ///< 1 / s^2 of the range growth (noise_reference_range_m of the model's params)
    double weight = 1;            ///< exponent on p(z_k | m, x): 1 = an independent detection, < 1 a repeated one
};

/// Prepares a detection of map class `map_class` from its box and ground footprint in the robot
/// frame. `noise_reference_range_m` > 0: a centre r > it (m) from the robot gets
/// noise_inv_scale2 = (noise_reference_range_m / r)^2 (the model's noise widened by r / it);
/// 0 = off. `weight`: the exponent of its likelihood (1 = the paper's).
PreparedDetection prepareDetection(int map_class, const geometry::Box3D& box_in_robot,
                                   const geometry::ConvexPolygon& footprint_in_robot, double noise_reference_range_m,
                                   double weight);

}  // namespace simp::maps
