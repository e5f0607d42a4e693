#pragma once
/// \file GroundTruthMatch.h
/// Matching of one 3D prediction to a ground-truth map object (paper Sec. "Statistical
/// Analysis of 3D Object Detections"): only objects of the same class whose centre lies within
/// delta of the prediction's centre are candidates; among several, the highest 3D IoU wins;
/// when none overlaps, the nearest centre; with no candidate the prediction is discarded.

#include <simp/geometry/Box3D.h>
#include <simp/world/ObjectMapData.h>

#include <optional>

namespace simp::stats {

/// Result of matchToGroundTruth().
struct GroundTruthMatch {
    std::size_t object_index = 0;  ///< index into ObjectMapData::objects
    double iou = 0.0;              ///< 3D IoU of prediction and object, [0, 1]
    double distance_m = 0.0;       ///< 3D distance between the two centres (m)
};

/// Matches `prediction_in_world` (world frame, any orientation) of class `class_id`
/// (index into `gt.class_names`) to an object of `gt`. `delta_m` > 0 is the centre-distance
/// gate (3D Euclidean, m). Returns nullopt when no object of the class is within delta.
/// \throw std::invalid_argument when delta_m is not a positive finite number.
std::optional<GroundTruthMatch> matchToGroundTruth(const geometry::Box3D& prediction_in_world, int class_id,
                                                   const world::ObjectMapData& gt, double delta_m);

}  // namespace simp::stats
