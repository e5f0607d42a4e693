#include <simp/maps/SensorModel.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace simp::maps {
namespace {

/// out = R(c, s) in + t, written into a caller's polygon (no construction per particle).
inline void transformInto(const geometry::ConvexPolygon& in, double c, double s, double tx, double ty,
                          geometry::ConvexPolygon& out) {
    out.n = in.n;
    for (std::size_t i = 0; i < in.n; ++i)
        out.v[i] = Eigen::Vector2d(c * in.v[i].x() - s * in.v[i].y() + tx, s * in.v[i].x() + c * in.v[i].y() + ty);
}

/// IoU (Eq. iouscore) of the detection, the robot at (c, s, tx, ty) and the detection's
/// centre at wc in the world, with one map footprint. Rectangular map objects (most: upright
/// boxes) are done in their own frame, where their edges are axis-aligned: separating axes
/// first (in the global case most pairs whose circles overlap do not intersect), then
/// clipping by coordinate compares. Other footprints: generic clipping in the world, the
/// moved footprint kept in `world` for the next object of the same pair (model O).
template <typename Scratch>
inline double pairIou(const PreparedDetection& det, double c, double s, double tx, double ty,
                      const Eigen::Vector2d& wc, const ObjectFootprint& of, Scratch& scratch) {
    if (det.area_m2 <= 0.0 || of.area_m2 <= 0.0) return 0.0;
    double inter = 0.0;
    if (of.is_rect) {
        const geometry::OrientedRect& r = of.rect;
        // Robot -> object frame: rotation R_o^T R(phi) = (rc, rs); the detection centre R_o^T (wc - c_o).
        const double rc = r.c * c + r.s * s, rs = r.c * s - r.s * c;
        const Eigen::Vector2d lc = r.toLocal(wc);
        if (det.is_rect) {
            // The box centre is the footprint's centre of symmetry (up to rounding).
            geometry::OrientedRect d;
            d.center = lc;
            d.c = rc * det.rect_robot.c - rs * det.rect_robot.s;
            d.s = rs * det.rect_robot.c + rc * det.rect_robot.s;
            d.hx = det.rect_robot.hx;
            d.hy = det.rect_robot.hy;
            inter = geometry::intersectionAreaWithAlignedRect(d, r.hx, r.hy);
        } else {
            geometry::ConvexPolygon& fp = scratch.local;
            const geometry::ConvexPolygon& off = det.offsets_robot;
            fp.n = off.n;
            for (std::size_t i = 0; i < off.n; ++i)
                fp.v[i] = Eigen::Vector2d(rc * off.v[i].x() - rs * off.v[i].y() + lc.x(),
                                          rs * off.v[i].x() + rc * off.v[i].y() + lc.y());
            inter = geometry::intersectionAreaWithAlignedRect(fp, r.hx, r.hy);
        }
    } else {
        if (!scratch.world_valid) {
            transformInto(det.footprint_robot, c, s, tx, ty, scratch.world);
            scratch.world_valid = true;
        }
        inter = geometry::intersectionArea(scratch.world, of.polygon);
    }
    return iouFromIntersection(inter, det.area_m2, of.area_m2);
}

bool needsProbabilityMap(SensorModelType t) { return t == SensorModelType::Simp || t == SensorModelType::D; }

void checkParams(const SensorModelParams& p) {
    if (!(p.eta > 0.0 && p.eta < 1.0)) throw std::invalid_argument("eta = " + std::to_string(p.eta) + " must be in (0, 1)");
    if (!(p.mp.resolution_m > 0.0)) throw std::invalid_argument("mp_resolution_m must be > 0");
    if (!(p.mp.min_probability > 0.0 && p.mp.min_probability < 1.0))
        throw std::invalid_argument("mp_min_probability must be in (0, 1)");
    if (!(p.edt_sigma_m > 0.0)) throw std::invalid_argument("edt_sigma_m must be > 0");
    if (!(p.edt_max_distance_m > 0.0)) throw std::invalid_argument("edt_max_distance_m must be > 0");
    if (!(p.edt_resolution_m > 0.0)) throw std::invalid_argument("edt_resolution_m must be > 0");
    if (!(p.noise_reference_range_m >= 0.0 && std::isfinite(p.noise_reference_range_m)))
        throw std::invalid_argument("noise_reference_range_m must be >= 0 (0 = off)");
}

}  // namespace

SensorModel::SensorModel(const world::ObjectMapData& data, const SensorModelParams& params)
    : m_params(params), m_footprints(computeMapFootprints(data)) {
    checkParams(params);
    m_log_eta = std::log(params.eta);
    m_exp_minus_1 = std::exp(-1.0);
    m_inv_two_sigma2 = 1.0 / (2.0 * params.edt_sigma_m * params.edt_sigma_m);
    if (needsProbabilityMap(params.type)) {
        m_mp = ObjectProbabilityMap(data, params.mp);
        for (std::size_t c = 0; c < m_mp.numClasses(); ++c) m_num_usable_objects += m_mp.objectsOf(static_cast<int>(c)).size();
    } else {
        m_num_usable_objects = data.objects.size();
    }
    if (params.type == SensorModelType::Edt)
        m_edt = EdtMap(m_footprints, params.edt_resolution_m, params.edt_max_distance_m);
}

bool SensorModel::scoresClass(int map_class) const {
    if (map_class < 0 || static_cast<std::size_t>(map_class) >= m_footprints.class_objects.size()) return false;
    return needsProbabilityMap(m_params.type) ? m_mp.hasClass(map_class)
                                              : !m_footprints.class_objects[static_cast<std::size_t>(map_class)].empty();
}

std::optional<PreparedDetection> SensorModel::prepare(int map_class, const geometry::Box3D& box_in_robot,
                                                      const geometry::ConvexPolygon& footprint_in_robot,
                                                      double weight) const {
    if (!scoresClass(map_class)) return std::nullopt;
    PreparedDetection d;
    d.map_class = map_class;
    d.center_robot_m = box_in_robot.center.head<2>();
    d.footprint_robot = footprint_in_robot;
    d.area_m2 = footprint_in_robot.area();
    d.offsets_robot.n = footprint_in_robot.n;
    for (std::size_t v = 0; v < footprint_in_robot.n; ++v) {
        d.offsets_robot.v[v] = footprint_in_robot.v[v] - d.center_robot_m;
        d.radius_m = std::max(d.radius_m, d.offsets_robot.v[v].norm());
    }
    if (const auto r = geometry::asRectangle(footprint_in_robot)) {
        d.is_rect = true;
        d.rect_robot = *r;
    }
    if (m_params.noise_reference_range_m > 0.0) {
        const double s = std::max(1.0, d.center_robot_m.norm() / m_params.noise_reference_range_m);
        d.noise_inv_scale2 = 1.0 / (s * s);
    }
    d.weight = weight;
    return d;
}

// ----------------------------------------------------------------------------------------------
// Per (pose, detection) kernels. The robot pose is (c, s) = (cos phi, sin phi) and t = (tx, ty).
template <SensorModelType T>
double SensorModel::kernel(const PreparedDetection& det, double c, double s, double tx, double ty,
                           Scratch& scratch) const {
    // Detection centre in the world for this pose.
    const double wx = c * det.center_robot_m.x() - s * det.center_robot_m.y() + tx;
    const double wy = s * det.center_robot_m.x() + c * det.center_robot_m.y() + ty;
    const double eta = m_params.eta;

    if constexpr (T == SensorModelType::Simp || T == SensorModelType::D) {
        // Eq. globaldist: p_o = max over the class's objects of p_o(c), o_max its argmax (raster).
        const auto hit = m_mp.lookup(det.map_class, wx, wy, det.noise_inv_scale2);
        if (hit.object < 0) return m_log_eta;  // p_o = 0: Eq. combined gives eta
        if constexpr (T == SensorModelType::D) {
            return std::log(hit.p + (1.0 - hit.p) * eta);  // Eq. combined with p_g = 1
        } else {
            // Eq. iouscore: p_g = exp(-(1 - IoU)) between the detection footprint and o_max's.
            const ObjectFootprint& of = m_footprints.objects[static_cast<std::size_t>(hit.object)];
            double p_g = m_exp_minus_1;  // IoU = 0
            const Eigen::Vector2d wc(wx, wy);
            if (circlesOverlap(wc, det.radius_m, of.circle_center_m, of.circle_radius_m)) {
                scratch.world_valid = false;
                p_g = m_iou_score(pairIou(det, c, s, tx, ty, wc, of, scratch));
            }
            return std::log(hit.p * p_g + (1.0 - hit.p) * eta);  // Eq. combined
        }
    } else if constexpr (T == SensorModelType::O) {
        // Best overlap with any object of the class; IoU plays the association probability.
        const Eigen::Vector2d wc(wx, wy);
        double best_iou = 0.0;
        scratch.world_valid = false;
        for (const std::int32_t o : m_footprints.class_objects[static_cast<std::size_t>(det.map_class)]) {
            const ObjectFootprint& of = m_footprints.objects[static_cast<std::size_t>(o)];
            if (!circlesOverlap(wc, det.radius_m, of.circle_center_m, of.circle_radius_m)) continue;
            best_iou = std::max(best_iou, pairIou(det, c, s, tx, ty, wc, of, scratch));
        }
        if (best_iou <= 0.0) return m_log_eta;
        const double p_g = m_iou_score(best_iou);  // Eq. iouscore
        return std::log(best_iou * p_g + (1.0 - best_iou) * eta);
    } else {
        // EDT-MCL: beam-end model of the centre, mixed with the same floor eta.
        const double d = m_edt.distance(det.map_class, wx, wy);
        const double p_hit = std::exp(-d * d * m_inv_two_sigma2 * det.noise_inv_scale2);
        return std::log(p_hit + (1.0 - p_hit) * eta);
    }
}

template <SensorModelType T>
void SensorModel::accumulate(const PreparedDetection* dets, std::size_t num_dets, const mrpt::math::TPose2D* poses,
                             std::size_t n, double* sum_log) const {
    Scratch scratch;  // moved footprints, reused for every pair
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = poses[i];
        const double c = std::cos(p.phi), s = std::sin(p.phi);
        double acc = 0.0;
        for (std::size_t k = 0; k < num_dets; ++k) acc += dets[k].weight * kernel<T>(dets[k], c, s, p.x, p.y, scratch);
        sum_log[i] += acc;
    }
}

double SensorModel::logLikelihood(const PreparedDetection& det, const mrpt::math::TPose2D& pose) const {
    const double c = std::cos(pose.phi), s = std::sin(pose.phi);
    Scratch fp;
    switch (m_params.type) {
        case SensorModelType::Simp: return kernel<SensorModelType::Simp>(det, c, s, pose.x, pose.y, fp);
        case SensorModelType::Edt: return kernel<SensorModelType::Edt>(det, c, s, pose.x, pose.y, fp);
        case SensorModelType::D: return kernel<SensorModelType::D>(det, c, s, pose.x, pose.y, fp);
        case SensorModelType::O: return kernel<SensorModelType::O>(det, c, s, pose.x, pose.y, fp);
    }
    return 0.0;
}

void SensorModel::accumulateLogLikelihoods(const PreparedDetection* dets, std::size_t num_dets,
                                           const mrpt::math::TPose2D* poses, std::size_t n, double* sum_log) const {
    if (num_dets == 0 || n == 0) return;
    switch (m_params.type) {
        case SensorModelType::Simp: accumulate<SensorModelType::Simp>(dets, num_dets, poses, n, sum_log); break;
        case SensorModelType::Edt: accumulate<SensorModelType::Edt>(dets, num_dets, poses, n, sum_log); break;
        case SensorModelType::D: accumulate<SensorModelType::D>(dets, num_dets, poses, n, sum_log); break;
        case SensorModelType::O: accumulate<SensorModelType::O>(dets, num_dets, poses, n, sum_log); break;
    }
}

}  // namespace simp::maps
