#include <simp/localization/DetectionPoseSampler.h>

#include <mrpt/math/wrap2pi.h>
#include <simp/geometry/Box3D.h>

#include <algorithm>
#include <cmath>

namespace simp::localization {
namespace {

// The pose of a frame at heading phi in which a point seen at `seen_in_frame` lies at `object_world`.
mrpt::math::TPose2D placeFrame(const Eigen::Vector2d& object_world, const Eigen::Vector2d& seen_in_frame, double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    return {object_world.x() - (c * seen_in_frame.x() - s * seen_in_frame.y()),
            object_world.y() - (s * seen_in_frame.x() + c * seen_in_frame.y()), phi};
}

}  // namespace

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
    const auto p = placeFrame(m_expected_centre_m[o], d.centre_robot_m, phi);
    return {p.x + dx, p.y + dy, phi};
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

std::vector<mrpt::math::TPose2D> DetectionPoseSampler::pairFits(const std::vector<FitWindow::Placed>& placed,
                                                                const PairFitParams& params,
                                                                std::size_t max_count) const {
    // Repeated detections of one object are one point (their mean): pairs of them say nothing.
    struct Point {
        int map_class;
        Eigen::Vector2d xy;
        int n;
    };
    std::vector<Point> points;
    const double r2 = params.merge_radius_m * params.merge_radius_m;
    for (const auto& d : placed) {
        if (d.map_class < 0 || static_cast<std::size_t>(d.map_class) >= m_by_class.size() ||
            m_by_class[static_cast<std::size_t>(d.map_class)].empty())
            continue;
        const Eigen::Vector2d xy(d.x, d.y);
        auto same = std::find_if(points.begin(), points.end(), [&](const Point& p) {
            return p.map_class == d.map_class && (p.xy / p.n - xy).squaredNorm() <= r2;
        });
        if (same != points.end())
            same->xy += xy, ++same->n;
        else
            points.push_back({d.map_class, xy, 1});
    }
    for (auto& p : points) p.xy /= p.n;
    struct Pair {
        std::size_t i, j;
        double separation;
    };
    std::vector<Pair> pairs;
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            const double sep = (points[j].xy - points[i].xy).norm();
            if (sep >= params.min_separation_m) pairs.push_back({i, j, sep});
        }
    std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.separation > b.separation; });
    std::vector<mrpt::math::TPose2D> out;
    for (const auto& pr : pairs) {
        const Point& p = points[pr.i];
        const Point& q = points[pr.j];
        const Eigen::Vector2d dpq = q.xy - p.xy;
        const double det_angle = std::atan2(dpq.y(), dpq.x());
        for (const std::size_t a : m_by_class[static_cast<std::size_t>(p.map_class)])
            for (const std::size_t b : m_by_class[static_cast<std::size_t>(q.map_class)]) {
                if (a == b) continue;
                const Eigen::Vector2d dab = m_expected_centre_m[b] - m_expected_centre_m[a];
                if (std::abs(dab.norm() - pr.separation) > params.tolerance_m) continue;
                if (out.size() >= max_count) return out;
                const double phi = mrpt::math::wrapToPi(std::atan2(dab.y(), dab.x()) - det_angle);
                out.push_back(placeFrame(m_expected_centre_m[a], p.xy, phi));
            }
    }
    return out;
}

}  // namespace simp::localization
