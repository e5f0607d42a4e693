#include <simp/localization/DetectionPoseSampler.h>

#include <mrpt/math/wrap2pi.h>
#include <simp/geometry/Box3D.h>

#include <algorithm>
#include <cmath>

namespace simp::localization {

DetectionPoseSampler::DetectionPoseSampler(const maps::CObjectMap& map, const FreeSpace& free_space,
                                           const DetectionPoseSamplerParams& params)
    : m_map(map), m_free(free_space), m_params(params) {
    const auto model = m_map.sensorModel();
    const auto& data = m_map.data();
    const auto& mp = model->probabilityMap();
    m_by_class.resize(data.class_names.size());
    m_expected_centre_m.resize(data.objects.size());
    for (std::size_t o = 0; o < data.objects.size(); ++o) {
        const int c = data.objects[o].class_id;
        if (c >= 0 && static_cast<std::size_t>(c) < m_by_class.size()) m_by_class[static_cast<std::size_t>(c)].push_back(o);
        m_expected_centre_m[o] = data.objects[o].box.center.head<2>();
        if (c >= 0 && mp.hasClass(c)) {
            const auto& objs = mp.objectsOf(c);
            if (std::find(objs.begin(), objs.end(), static_cast<std::int32_t>(o)) != objs.end())
                m_expected_centre_m[o] = mp.distribution(o).mean_world_m;
        }
    }
}

std::vector<DetectionPoseSampler::Usable> DetectionPoseSampler::usableDetections(
    const std::vector<WeightedObservation>& observations) const {
    const auto model = m_map.sensorModel();
    std::vector<Usable> dets;
    for (const auto& wo : observations) {
        for (std::size_t k = 0; k < wo.obs->size(); ++k) {
            const int c = m_map.usableClassOf(*wo.obs, k);
            if (c < 0 || static_cast<std::size_t>(c) >= m_by_class.size() || m_by_class[static_cast<std::size_t>(c)].empty())
                continue;
            if (!model->prepare(c, wo.obs->boxInRobot(k), wo.obs->footprintInRobot(k))) continue;
            const geometry::Box3D box = geometry::canonicalizeUpright(wo.obs->boxInRobot(k));
            const double a = box.size.x(), b = box.size.y();
            dets.push_back({box.center.head<2>(), geometry::yawOf(box),
                            std::min(a, b) >= m_params.square_ratio * std::max(a, b) ? 4 : 2, c});
        }
    }
    return dets;
}

mrpt::math::TPose2D DetectionPoseSampler::fit(const Usable& d, std::size_t o, int turn, double dphi, double dx,
                                              double dy) const {
    // Robot heading that turns the detected box onto the object's (modulo the box symmetry).
    const double phi = mrpt::math::wrapToPi(geometry::yawOf(m_map.data().objects[o].box) - d.yaw_robot_rad +
                                            turn * (2.0 * M_PI / d.symmetries) + dphi);
    const Eigen::Vector2d& target = m_expected_centre_m[o];
    const double c = std::cos(phi), s = std::sin(phi);
    return {target.x() - (c * d.centre_robot_m.x() - s * d.centre_robot_m.y()) + dx,
            target.y() - (s * d.centre_robot_m.x() + c * d.centre_robot_m.y()) + dy, phi};
}

std::vector<mrpt::math::TPose2D> DetectionPoseSampler::sample(const std::vector<WeightedObservation>& observations,
                                                              std::size_t count,
                                                              mrpt::random::CRandomGenerator& rng) const {
    std::vector<mrpt::math::TPose2D> out;
    const std::vector<Usable> dets = usableDetections(observations);
    if (dets.empty() || count == 0) return out;
    const std::size_t max_draws = 4 * count;
    for (std::size_t draw = 0; draw < max_draws && out.size() < count; ++draw) {
        const auto& d = dets[std::min(dets.size() - 1, static_cast<std::size_t>(rng.drawUniform(0.0, 1.0) * dets.size()))];
        const auto& objs = m_by_class[static_cast<std::size_t>(d.map_class)];
        const std::size_t o = objs[std::min(objs.size() - 1, static_cast<std::size_t>(rng.drawUniform(0.0, 1.0) * objs.size()))];
        const int turn = std::min(d.symmetries - 1, static_cast<int>(rng.drawUniform(0.0, 1.0) * d.symmetries));
        // The draws in this order (heading, then x, then y) keep a seed's sequence unchanged.
        const double dphi = rng.drawGaussian1D(0.0, m_params.heading_std_rad);
        const double dx = rng.drawGaussian1D(0.0, m_params.position_std_m);
        const double dy = rng.drawGaussian1D(0.0, m_params.position_std_m);
        const auto p = fit(d, o, turn, dphi, dx, dy);
        if (m_free.isFree(p.x, p.y)) out.push_back(p);
    }
    return out;
}

std::vector<mrpt::math::TPose2D> DetectionPoseSampler::candidates(const std::vector<WeightedObservation>& observations,
                                                                  std::size_t max_count) const {
    std::vector<mrpt::math::TPose2D> out;
    for (const auto& d : usableDetections(observations))
        for (const std::size_t o : m_by_class[static_cast<std::size_t>(d.map_class)])
            for (int turn = 0; turn < d.symmetries; ++turn) {
                if (out.size() >= max_count) return out;
                const auto p = fit(d, o, turn, 0.0, 0.0, 0.0);
                if (m_free.isFree(p.x, p.y)) out.push_back(p);
            }
    return out;
}

}  // namespace simp::localization
