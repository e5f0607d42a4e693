#include <simp/localization/DetectionPoseSampler.h>

#include <mrpt/math/wrap2pi.h>
#include <simp/geometry/Box3D.h>

#include <algorithm>
#include <cmath>

namespace simp::localization {
namespace {

struct UsableDetection {
    Eigen::Vector2d centre_robot_m;
    double yaw_robot_rad = 0;
    bool square = false;
    int map_class = -1;
};

}  // namespace

DetectionPoseSampler::DetectionPoseSampler(const maps::CObjectMap& map, const FreeSpace& free_space,
                                           const DetectionPoseSamplerParams& params)
    : m_map(map), m_free(free_space), m_params(params) {}

std::vector<mrpt::math::TPose2D> DetectionPoseSampler::sample(const std::vector<WeightedObservation>& observations,
                                                              std::size_t count,
                                                              mrpt::random::CRandomGenerator& rng) const {
    std::vector<mrpt::math::TPose2D> out;
    const auto model = m_map.sensorModel();
    const auto& data = m_map.data();
    // Objects per class, and where each one's detections are expected (Eq. shiftdist mean).
    std::vector<std::vector<std::size_t>> by_class(data.class_names.size());
    for (std::size_t o = 0; o < data.objects.size(); ++o) {
        const int c = data.objects[o].class_id;
        if (c >= 0 && static_cast<std::size_t>(c) < by_class.size()) by_class[static_cast<std::size_t>(c)].push_back(o);
    }
    const auto& mp = model->probabilityMap();
    const auto expectedCentre = [&](std::size_t o, int c) -> Eigen::Vector2d {
        if (mp.hasClass(c)) {
            const auto& objs = mp.objectsOf(c);
            if (std::find(objs.begin(), objs.end(), static_cast<std::int32_t>(o)) != objs.end())
                return mp.distribution(o).mean_world_m;
        }
        return data.objects[o].box.center.head<2>();
    };

    std::vector<UsableDetection> dets;
    for (const auto& wo : observations) {
        for (std::size_t k = 0; k < wo.obs->size(); ++k) {
            const int c = m_map.usableClassOf(*wo.obs, k);
            if (c < 0 || static_cast<std::size_t>(c) >= by_class.size() || by_class[static_cast<std::size_t>(c)].empty())
                continue;
            if (!model->prepare(c, wo.obs->boxInRobot(k), wo.obs->footprintInRobot(k))) continue;
            const geometry::Box3D box = geometry::canonicalizeUpright(wo.obs->boxInRobot(k));
            const double a = box.size.x(), b = box.size.y();
            dets.push_back({box.center.head<2>(), geometry::yawOf(box),
                            std::min(a, b) >= m_params.square_ratio * std::max(a, b), c});
        }
    }
    if (dets.empty() || count == 0) return out;

    const std::size_t max_draws = 4 * count;
    for (std::size_t draw = 0; draw < max_draws && out.size() < count; ++draw) {
        const auto& d = dets[std::min(dets.size() - 1, static_cast<std::size_t>(rng.drawUniform(0.0, 1.0) * dets.size()))];
        const auto& objs = by_class[static_cast<std::size_t>(d.map_class)];
        const std::size_t o = objs[std::min(objs.size() - 1, static_cast<std::size_t>(rng.drawUniform(0.0, 1.0) * objs.size()))];
        const int symmetries = d.square ? 4 : 2;
        const int turn = std::min(symmetries - 1, static_cast<int>(rng.drawUniform(0.0, 1.0) * symmetries));
        // Robot heading that turns the detected box onto the object's (modulo the box symmetry).
        const double phi = mrpt::math::wrapToPi(geometry::yawOf(data.objects[o].box) - d.yaw_robot_rad +
                                                turn * (2.0 * M_PI / symmetries) +
                                                rng.drawGaussian1D(0.0, m_params.heading_std_rad));
        const Eigen::Vector2d target = expectedCentre(o, d.map_class);
        const double c = std::cos(phi), s = std::sin(phi);
        const double x = target.x() - (c * d.centre_robot_m.x() - s * d.centre_robot_m.y()) +
                         rng.drawGaussian1D(0.0, m_params.position_std_m);
        const double y = target.y() - (s * d.centre_robot_m.x() + c * d.centre_robot_m.y()) +
                         rng.drawGaussian1D(0.0, m_params.position_std_m);
        if (m_free.isFree(x, y)) out.push_back({x, y, phi});
    }
    return out;
}

}  // namespace simp::localization
