#pragma once
/// \file ObjectProbabilityMap.h
/// The object probability map m_p (paper Sec. "Statistical Analysis"): per class, the
/// per-object centre distributions (Eq. shiftdist) rasterized so that Eq. globaldist,
/// max over the class's objects of p_o(c), and its argmax o_max cost O(1) per point.

#include <simp/maps/GridGeometry.h>
#include <simp/model/ObjectDistribution.h>
#include <simp/world/ObjectMapData.h>

#include <cstdint>
#include <vector>

namespace simp::maps {

class ObjectProbabilityMap {
   public:
    struct Options {
        double resolution_m = 0.05;       ///< raster cell side (m)
        double min_probability = 1e-4;    ///< support: cells where every p_o < this store "no object"
        bool skip_classes_without_noise = false;  ///< false: a class lacking a noise model is an error
        /// > 0: an object with neither its own nor its class's noise model gets an isotropic
        /// Gaussian of this std (m) instead (then skip_classes_without_noise does not apply).
        double unmodelled_noise_std_m = 0.0;
        /// 0 = each object's noise model as is (the paper's). > 0: the model's spread minus the
        /// object's own footprint (model::withoutFootprint), floored at this fraction of its std.
        double centre_noise_floor = 0.0;
    };

    /// The result of Eq. globaldist at a point.
    struct Lookup {
        std::int32_t object = -1;  ///< o_max: index into ObjectMapData::objects, -1 = none
        double p = 0.0;            ///< p_o(c) of o_max, in [0, 1]; 0 when object == -1
    };

    ObjectProbabilityMap() = default;
    /// Precomputes the per-class rasters. Throws std::invalid_argument naming the class and the
    /// object when an object has no noise model (its own or its class's), unless
    /// skip_classes_without_noise (then the whole class is left out, see skippedClasses()).
    ObjectProbabilityMap(const world::ObjectMapData& data, const Options& options);

    /// Eq. globaldist from the raster: o_max = the object with the largest p_o at the centre
    /// of the cell holding (x, y) (world, m); p = p_{o_max}(x, y) evaluated exactly.
    /// Outside the class raster or beyond every object's support: {-1, 0}. `inv_scale2` widens
    /// o_max's distribution (ObjectDistribution::probability); o_max and the support are those of
    /// the model's own Sigma.
    Lookup lookup(int class_id, double x_m, double y_m, double inv_scale2 = 1.0) const {
        const ClassRaster& r = m_classes[static_cast<std::size_t>(class_id)];
        const std::int64_t cell = r.grid.cellIndex(x_m, y_m);
        if (cell < 0) return {};
        const std::int32_t o = r.best[static_cast<std::size_t>(cell)];
        if (o < 0) return {};
        return {o, m_distributions[static_cast<std::size_t>(o)].probability(x_m, y_m, inv_scale2)};
    }

    /// Eq. globaldist by brute force over all the class's objects (reference for tests).
    Lookup bruteForce(int class_id, double x_m, double y_m) const;

    /// True when the class has at least one object with a distribution.
    bool hasClass(int class_id) const {
        return class_id >= 0 && static_cast<std::size_t>(class_id) < m_classes.size() &&
               !m_classes[static_cast<std::size_t>(class_id)].objects.empty();
    }
    std::size_t numClasses() const { return m_classes.size(); }
    const GridGeometry& grid(int class_id) const { return m_classes.at(static_cast<std::size_t>(class_id)).grid; }
    /// Objects of the class that take part (indices into ObjectMapData::objects).
    const std::vector<std::int32_t>& objectsOf(int class_id) const {
        return m_classes.at(static_cast<std::size_t>(class_id)).objects;
    }
    /// Distribution of object o (valid only for objects listed by objectsOf()).
    const model::ObjectDistribution& distribution(std::size_t o) const { return m_distributions.at(o); }
    const std::vector<int>& skippedClasses() const { return m_skipped_classes; }
    const Options& options() const { return m_options; }

   private:
    struct ClassRaster {
        GridGeometry grid;                 ///< covers the union of the class's supports
        std::vector<std::int32_t> best;    ///< per cell: o_max at the cell centre, -1 = none
        std::vector<std::int32_t> objects; ///< objects of the class
    };
    Options m_options;
    std::vector<ClassRaster> m_classes;              ///< per class id
    std::vector<model::ObjectDistribution> m_distributions; ///< per object index
    std::vector<int> m_skipped_classes;
};

}  // namespace simp::maps
