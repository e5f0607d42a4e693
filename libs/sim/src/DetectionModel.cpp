#include <simp/sim/DetectionModel.h>
#include <simp/model/NoiseFrame.h>
#include <simp/sim/Furniture.h>

#include <algorithm>
#include <cmath>

namespace simp::sim {
namespace {

float drawScore(double mean, double std, Rng& rng) {
    return static_cast<float>(std::clamp(rng.normal(mean, std), 0.01, 1.0));
}

std::optional<obs::Detection3D> finish(const camera::PinholeCamera& view, obs::Detection3D d) {
    obs::ImageBox2D b;
    if (!imageBoxOf(view, d.box_in_camera, b)) return std::nullopt;
    d.box_2d = b;
    return d;
}

}  // namespace

model::NoiseModel noiseFor(const world::ObjectMapData& map, const world::MapObject& o, const DetectorParams& p) {
    if (o.noise) return *o.noise;
    if (o.class_id >= 0 && static_cast<std::size_t>(o.class_id) < map.class_noise.size() &&
        map.class_noise[static_cast<std::size_t>(o.class_id)])
        return *map.class_noise[static_cast<std::size_t>(o.class_id)];
    model::NoiseModel m;
    m.mean_m.setZero();
    m.cov_m2 = Eigen::Matrix2d::Identity() * p.default_noise_std_m * p.default_noise_std_m;
    m.exponent_b = 2.0;
    return m;
}

model::NoiseModel centreNoiseOf(const model::NoiseModel& model, const world::MapObject& o, const DetectorParams& p) {
    if (!p.noise_model_includes_extent) return model;
    return model::withoutFootprint(model, o.box, o.noiseSource(), p.min_centre_noise_fraction);
}

geometry::Box3D worldBoxToCamera(const geometry::Box3D& upright_world_box, const Eigen::Isometry3d& T_camera_world) {
    const geometry::Box3D b = upright_world_box.transformed(T_camera_world);
    // new axes: x = old x, y = -old z (down), z = old y; right-handed (det = +1)
    Eigen::Matrix3d P;
    P << 1, 0, 0,  //
        0, 0, 1,   //
        0, -1, 0;
    geometry::Box3D out;
    out.center = b.center;
    out.R = b.R * P;
    out.size = Eigen::Vector3d(b.size.x(), b.size.z(), b.size.y());
    return out;
}

Eigen::Vector2d centreOffsetInWorld(const camera::PinholeCamera& view, const world::MapObject& o, const model::NoiseModel& noise,
                                    const DetectorParams& p, std::uint64_t noise_seed, Rng& rng) {
    model::NoiseModel zero_mean = noise;
    zero_mean.mean_m.setZero();
    const Eigen::Vector2d cam = view.world_T_camera.translation().head<2>();
    const Eigen::Vector2d ray = o.box.center.head<2>() - cam;
    const double dist = ray.norm();
    // persistent part: one draw per (sequence, object, viewpoint cell)
    Eigen::Vector2d e = Eigen::Vector2d::Zero();
    const double f = p.persistent_variance_fraction;
    if (f > 0) {
        const double bearing = std::atan2(-ray.y(), -ray.x());  // object -> camera (rad)
        const auto cell_a = static_cast<std::int64_t>(std::floor(bearing * 180.0 / M_PI / p.viewpoint_bin_deg));
        const auto cell_d = static_cast<std::int64_t>(std::floor(dist / p.viewpoint_bin_m));
        std::uint64_t h = noise_seed ^ 0x9E3779B97F4A7C15ULL;
        for (const std::int64_t v : {static_cast<std::int64_t>(o.id), cell_a, cell_d})
            h = (h ^ static_cast<std::uint64_t>(v)) * 0x100000001B3ULL + 0x9E3779B97F4A7C15ULL;
        Rng view_rng(h);
        e += std::sqrt(f) * sampleCentreOffset(zero_mean, view_rng);
    }
    if (f < 1) e += std::sqrt(1.0 - f) * sampleCentreOffset(zero_mean, rng);
    // Eq. shiftdist: the class distribution rotated into the object's ground frame
    const Eigen::Rotation2Dd R_o(model::noiseFrameYaw(o.box, o.noiseSource()));  // own noise: box frame; class noise: noise frame
    Eigen::Vector2d dev = R_o * e;
    if (dist > 1e-9) {  // depth error along the viewing ray grows with distance
        const Eigen::Vector2d u = ray / dist;
        dev += (dist / p.reference_distance_m - 1.0) * u.dot(dev) * u;
    }
    return R_o * noise.mean_m + dev;
}

std::optional<obs::Detection3D> detectObject(const camera::PinholeCamera& view, const world::MapObject& o,
                                             const model::NoiseModel& noise, std::size_t num_classes,
                                             const DetectorParams& p, Rng& rng, std::uint64_t noise_seed) {
    if (!rng.bernoulli(p.detection_probability)) return std::nullopt;
    const double yaw = geometry::yawOf(o.box);
    const Eigen::Vector2d c_xy = o.box.center.head<2>() + centreOffsetInWorld(view, o, noise, p, noise_seed, rng);
    const double z = o.box.center.z() + rng.normal(0.0, p.z_std_m);
    Eigen::Vector3d size = o.box.size;
    for (int k = 0; k < 3; ++k) size[k] = std::max(0.02, size[k] * (1.0 + rng.normal(0.0, p.size_std_fraction)));
    const double yaw_det = yaw + rng.normal(0.0, p.yaw_std_rad);

    obs::Detection3D d;
    d.class_id = static_cast<std::uint16_t>(o.class_id);
    d.confidence = drawScore(p.confidence_true_mean, p.confidence_true_std, rng);
    if (num_classes > 1 && rng.bernoulli(p.wrong_class_probability)) {
        std::size_t k = rng.index(num_classes - 1);
        if (k >= static_cast<std::size_t>(o.class_id)) ++k;
        d.class_id = static_cast<std::uint16_t>(k);
        d.confidence = drawScore(p.confidence_false_mean, p.confidence_false_std, rng);
    }
    if (d.confidence < p.min_confidence) return std::nullopt;
    const geometry::Box3D world_box = geometry::makeUprightBox({c_xy.x(), c_xy.y(), z}, size, yaw_det);
    d.box_in_camera = worldBoxToCamera(world_box, view.world_T_camera.inverse());
    return finish(view, d);
}

std::optional<obs::Detection3D> phantomDetection(const camera::PinholeCamera& view, const Raster& walls,
                                                 const std::vector<std::string>& class_names,
                                                 const FalsePositiveParams& fp, const DetectorParams& p, Rng& rng) {
    if (class_names.empty()) return std::nullopt;
    const std::size_t cls = rng.index(class_names.size());
    double w = 0.5, d = 0.5, h = 0.5, z0 = 0;
    try {
        const auto& t = objectTemplate(class_names[cls]);
        w = rng.uniform(t.w_min, t.w_max);
        d = rng.uniform(t.d_min, t.d_max);
        h = rng.uniform(t.h_min, t.h_max);
        z0 = t.z_bottom_m;
    } catch (const std::invalid_argument&) {
        // a class without a template (imported label set): a half-metre cube
    }
    const double hfov = std::atan2(0.5 * view.widthPx(), view.fx());
    const Eigen::Vector3d cam = view.world_T_camera.translation();
    const Eigen::Vector3d axis = view.world_T_camera.linear().col(2);
    const double cam_yaw = std::atan2(axis.y(), axis.x());
    for (int attempt = 0; attempt < 10; ++attempt) {
        const double range = rng.uniform(fp.range_min_m, fp.range_max_m);
        const double bearing = cam_yaw + rng.uniform(-hfov, hfov);
        const Eigen::Vector2d c(cam.x() + range * std::cos(bearing), cam.y() + range * std::sin(bearing));
        if (!lineOfSight(walls, cam.head<2>(), c)) continue;
        obs::Detection3D det;
        det.class_id = static_cast<std::uint16_t>(cls);
        det.confidence = drawScore(p.confidence_false_mean, p.confidence_false_std, rng);
        const double yaw = rng.uniform(-M_PI, M_PI);
        if (det.confidence < p.min_confidence) return std::nullopt;
        const auto box = geometry::makeUprightBox({c.x(), c.y(), z0 + h / 2}, {w, d, h}, yaw);
        det.box_in_camera = worldBoxToCamera(box, view.world_T_camera.inverse());
        return finish(view, det);
    }
    return std::nullopt;
}

}  // namespace simp::sim
