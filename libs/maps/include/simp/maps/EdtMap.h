#pragma once
/// \file EdtMap.h
/// Per-class Euclidean distance transform of the map objects' footprints, for the EDT-MCL
/// baseline (paper Sec. "Baseline Comparisons"): a beam-end style model of detection centres.

#include <simp/maps/GridGeometry.h>
#include <simp/maps/MapFootprints.h>

#include <vector>

namespace simp::maps {

class EdtMap {
   public:
    EdtMap() = default;
    /// Rasterizes each class's footprints at `resolution_m` over their bounds grown by
    /// `max_distance_m`, then runs cv::distanceTransform (L2, precise mask).
    EdtMap(const MapFootprints& footprints, double resolution_m, double max_distance_m);

    /// Distance (m) from the world point to the nearest footprint of the class, 0 inside one,
    /// clamped to max_distance_m (also outside the raster and for classes without objects).
    double distance(int class_id, double x_m, double y_m) const {
        if (class_id < 0 || static_cast<std::size_t>(class_id) >= m_classes.size()) return m_max_distance_m;
        const ClassEdt& c = m_classes[static_cast<std::size_t>(class_id)];
        const std::int64_t cell = c.grid.cellIndex(x_m, y_m);
        if (cell < 0) return m_max_distance_m;
        return c.distance_m[static_cast<std::size_t>(cell)];
    }

   private:
    struct ClassEdt {
        GridGeometry grid;
        std::vector<float> distance_m;  ///< per cell (m), clamped to max_distance_m
    };
    std::vector<ClassEdt> m_classes;
    double m_max_distance_m = 2.0;
};

}  // namespace simp::maps
