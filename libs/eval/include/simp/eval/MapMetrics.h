#pragma once
/// \file MapMetrics.h
/// The paper's object-map metrics (Table I): per class, objects of a predicted map are
/// matched one-to-one to the ground-truth objects of the same class, then IoU, precision
/// and recall are computed per class and averaged over the classes.
///
/// Definitions (doc/evaluation.md):
///  - Classes are compared by name (the two maps may order their class lists differently).
///    The classes evaluated are those with at least one object in either map (restricted to
///    MapMatchParams::classes when that list is given).
///  - Matching per class: Hungarian algorithm (simp::geometry::solveAssignment) on the cost
///    1 - IoU_fp, IoU_fp = IoU of the ground footprints (convex polygons, exact). A pair is
///    admissible only when IoU_fp > 0 and the planar distance of the box centres is <=
///    max_center_dist_m; inadmissible pairs never match.
///  - iou = mean IoU_fp over the matched pairs (0 when the class has no match);
///    iou_3d = mean 3D IoU (simp::geometry::iou3D) of the same pairs (0 when none);
///    precision = matched / predicted (0 when nothing is predicted);
///    recall = matched / ground truth (0 when the ground truth has none).
///  - The averages are the plain means of the per-class values over the evaluated classes.

#include <simp/world/ObjectMapData.h>

#include <map>
#include <string>
#include <vector>

namespace simp::eval {

struct MapMatchParams {
    double max_center_dist_m = 1.0;  ///< centre-distance gate (m, planar) of an admissible pair
    /// When not empty: evaluate only these classes (objects of other classes are left out of both
    /// maps), e.g. the classes a mapper is configured to build, as the paper's Table I does.
    std::vector<std::string> classes;
};

/// One matched pair: indices into ObjectMapData::objects of each map.
struct ObjectMatch {
    std::size_t gt_index = 0;
    std::size_t pred_index = 0;
    double iou_footprint = 0;  ///< IoU of the ground footprints
    double iou_3d = 0;         ///< IoU of the 3D boxes
    double center_dist_m = 0;  ///< planar centre distance (m)
};

/// Metrics of one class.
struct ClassMapMetrics {
    std::size_t n_gt = 0, n_pred = 0, n_matched = 0;
    double iou = 0;        ///< mean footprint IoU of matched pairs
    double iou_3d = 0;     ///< mean 3D IoU of matched pairs (extra, not in the paper's table)
    double precision = 0;  ///< n_matched / n_pred
    double recall = 0;     ///< n_matched / n_gt
};

struct MapMetrics {
    std::map<std::string, ClassMapMetrics> per_class;  ///< class name -> metrics (sorted by name)
    double iou = 0, iou_3d = 0, precision = 0, recall = 0;  ///< means over per_class
    std::vector<ObjectMatch> matches;                  ///< all matched pairs, every class
    std::vector<std::size_t> missed_gt;                ///< ground-truth objects left unmatched
    std::vector<std::size_t> false_pred;               ///< predicted objects left unmatched
};

/// Evaluates `predicted` against `ground_truth`.
/// \throw std::invalid_argument naming the map and object index when an object's class id is
///        outside its class list or its box is not valid, and when neither map has any object.
MapMetrics evaluateMap(const world::ObjectMapData& ground_truth, const world::ObjectMapData& predicted,
                       const MapMatchParams& params = {});

}  // namespace simp::eval
