#include <simp/maps/ObjectProbabilityMap.h>
#include <simp/model/NoiseFrame.h>
#include <simp/model/NoiseModel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace simp::maps {
namespace {

std::string objectWhere(const world::ObjectMapData& data, std::size_t i) {
    return "object #" + std::to_string(i) + " (id " + std::to_string(data.objects[i].id) + ")";
}

}  // namespace

ObjectProbabilityMap::ObjectProbabilityMap(const world::ObjectMapData& data, const Options& options)
    : m_options(options) {
    if (!(options.resolution_m > 0.0) || !std::isfinite(options.resolution_m))
        throw std::invalid_argument("object probability map: resolution must be > 0 m");
    if (!(options.unmodelled_noise_std_m >= 0.0) || !std::isfinite(options.unmodelled_noise_std_m))
        throw std::invalid_argument("object probability map: unmodelled_noise_std_m must be >= 0 m (0 = none)");
    if (!(options.centre_noise_floor >= 0.0 && options.centre_noise_floor <= 1.0))
        throw std::invalid_argument("object probability map: centre_noise_floor must be in [0, 1] (0 = the model as is)");
    const std::size_t num_classes = data.class_names.size();
    m_classes.resize(num_classes);
    m_distributions.resize(data.objects.size());

    // Which objects take part, and their distributions (Eq. shiftdist).
    std::vector<bool> class_missing_noise(num_classes, false);
    for (std::size_t i = 0; i < data.objects.size(); ++i) {
        const auto& obj = data.objects[i];
        if (obj.class_id < 0 || static_cast<std::size_t>(obj.class_id) >= num_classes)
            throw std::invalid_argument("object map: " + objectWhere(data, i) + " has class id " +
                                        std::to_string(obj.class_id) + " outside the class list");
        auto noise = data.noiseOf(obj);
        // Only a model from the map is a footprint fit; the isotropic default below is a centre noise.
        if (noise && options.centre_noise_floor > 0.0)
            noise = model::withoutFootprint(*noise, obj.box, obj.noiseSource(), options.centre_noise_floor);
        if (!noise && options.unmodelled_noise_std_m > 0.0) {
            noise = model::NoiseModel{};
            noise->cov_m2 = Eigen::Matrix2d::Identity() * options.unmodelled_noise_std_m * options.unmodelled_noise_std_m;
        }
        const std::string& cls = data.class_names[static_cast<std::size_t>(obj.class_id)];
        if (!noise) {
            if (!options.skip_classes_without_noise)
                throw std::invalid_argument("object map: class '" + cls + "' has no noise model (" +
                                            objectWhere(data, i) +
                                            " has neither its own nor a class one); the simp and d sensor "
                                            "models need one (or set skip_classes_without_noise=true)");
            class_missing_noise[static_cast<std::size_t>(obj.class_id)] = true;
            continue;
        }
        try {
            m_distributions[i] = model::makeObjectDistribution(obj.box, *noise, obj.noiseSource());
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("object map: " + objectWhere(data, i) + " of class '" + cls + "': " + e.what());
        }
        m_classes[static_cast<std::size_t>(obj.class_id)].objects.push_back(static_cast<std::int32_t>(i));
    }
    for (std::size_t c = 0; c < num_classes; ++c)
        if (class_missing_noise[c]) {
            m_classes[c].objects.clear();
            m_skipped_classes.push_back(static_cast<int>(c));
        }

    // Per class: raster over the union of the supports, argmax of p_o at each cell centre.
    for (auto& cls : m_classes) {
        if (cls.objects.empty()) continue;
        double x_min = std::numeric_limits<double>::infinity(), y_min = x_min;
        double x_max = -x_min, y_max = -x_min;
        std::vector<double> half_x, half_y;  // support half extents per object (m)
        for (const std::int32_t o : cls.objects) {
            const auto& d = m_distributions[static_cast<std::size_t>(o)];
            const double m_s = model::supportMahalanobisRadius(2.0 * d.half_b, options.min_probability);
            half_x.push_back(m_s * d.sigma_x_m);  // exact x extent of the ellipse m <= m_s
            half_y.push_back(m_s * d.sigma_y_m);
            x_min = std::min(x_min, d.mean_world_m.x() - half_x.back());
            x_max = std::max(x_max, d.mean_world_m.x() + half_x.back());
            y_min = std::min(y_min, d.mean_world_m.y() - half_y.back());
            y_max = std::max(y_max, d.mean_world_m.y() + half_y.back());
        }
        cls.grid = GridGeometry::covering(x_min, y_min, x_max, y_max, options.resolution_m);
        if (cls.grid.cellCount() > (std::size_t{1} << 28))
            throw std::invalid_argument("object probability map: raster too large (" +
                                        std::to_string(cls.grid.nx) + " x " + std::to_string(cls.grid.ny) +
                                        " cells); increase the resolution or check the noise models");
        cls.best.assign(cls.grid.cellCount(), -1);
        std::vector<float> best_p(cls.grid.cellCount(), 0.0f);
        for (std::size_t j = 0; j < cls.objects.size(); ++j) {
            const std::int32_t o = cls.objects[j];
            const auto& d = m_distributions[static_cast<std::size_t>(o)];
            const auto& g = cls.grid;
            const int ix0 = std::max(0, static_cast<int>(std::floor((d.mean_world_m.x() - half_x[j] - g.x0_m) * g.inv_resolution)));
            const int ix1 = std::min(g.nx - 1, static_cast<int>(std::floor((d.mean_world_m.x() + half_x[j] - g.x0_m) * g.inv_resolution)));
            const int iy0 = std::max(0, static_cast<int>(std::floor((d.mean_world_m.y() - half_y[j] - g.y0_m) * g.inv_resolution)));
            const int iy1 = std::min(g.ny - 1, static_cast<int>(std::floor((d.mean_world_m.y() + half_y[j] - g.y0_m) * g.inv_resolution)));
            for (int iy = iy0; iy <= iy1; ++iy)
                for (int ix = ix0; ix <= ix1; ++ix) {
                    const double p = d.probability(g.cellCenterX(ix), g.cellCenterY(iy));
                    const std::size_t cell = static_cast<std::size_t>(iy) * static_cast<std::size_t>(g.nx) + static_cast<std::size_t>(ix);
                    if (p >= options.min_probability && p > best_p[cell]) {
                        best_p[cell] = static_cast<float>(p);
                        cls.best[cell] = o;
                    }
                }
        }
    }
}

ObjectProbabilityMap::Lookup ObjectProbabilityMap::bruteForce(int class_id, double x_m, double y_m) const {
    Lookup best;
    if (!hasClass(class_id)) return best;
    for (const std::int32_t o : m_classes[static_cast<std::size_t>(class_id)].objects) {
        const double p = m_distributions[static_cast<std::size_t>(o)].probability(x_m, y_m);
        if (p > best.p) best = {o, p};
    }
    return best;
}

}  // namespace simp::maps
