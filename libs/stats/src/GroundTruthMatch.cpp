/// \file GroundTruthMatch.cpp
#include <simp/geometry/Box3DIoU.h>
#include <simp/stats/GroundTruthMatch.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace simp::stats {

std::optional<GroundTruthMatch> matchToGroundTruth(const geometry::Box3D& prediction_in_world, int class_id,
                                                   const world::ObjectMapData& gt, double delta_m) {
    if (!(delta_m > 0.0) || !std::isfinite(delta_m))
        throw std::invalid_argument("matchToGroundTruth: delta must be a positive number of metres, got " +
                                    std::to_string(delta_m));
    std::optional<GroundTruthMatch> best_overlap, nearest;
    for (std::size_t i = 0; i < gt.objects.size(); ++i) {
        const world::MapObject& o = gt.objects[i];
        if (o.class_id != class_id) continue;
        const double dist = (o.box.center - prediction_in_world.center).norm();
        if (!(dist < delta_m)) continue;  // gate: centre within delta
        const double overlap = geometry::iou3D(prediction_in_world, o.box);
        const GroundTruthMatch m{i, overlap, dist};
        if (overlap > 0.0 && (!best_overlap || overlap > best_overlap->iou)) best_overlap = m;
        if (!nearest || dist < nearest->distance_m) nearest = m;
    }
    return best_overlap ? best_overlap : nearest;
}

}  // namespace simp::stats
