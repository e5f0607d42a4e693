#pragma once
/// \file DetectionModel.h
/// The simulated 3D object detector: noisy boxes of visible objects (centre noise from the
/// per-class model, paper Eq. perclassdist / shiftdist), misses, wrong labels, phantoms, scores.

#include <simp/obs/Detection3D.h>
#include <simp/sim/Random.h>
#include <simp/sim/Raster.h>
#include <simp/sim/SensorParams.h>
#include <simp/sim/Visibility.h>
#include <simp/world/ObjectMapData.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::sim {

/// The centre-noise model used for object `o`: its own, else its class's, else an isotropic
/// Gaussian of std default_noise_std_m.
model::NoiseModel noiseFor(const world::ObjectMapData& map, const world::MapObject& o, const DetectorParams& p);

/// The centre noise of detections of `o` given its noise model `model` (noiseFor()): `model` itself
/// unless p.noise_model_includes_extent; then model::withoutFootprint(model, o's box, o's noise
/// source, min_centre_noise_fraction).
model::NoiseModel centreNoiseOf(const model::NoiseModel& model, const world::MapObject& o, const DetectorParams& p);

/// An upright world box (local z up) as a camera-frame box with the detector's axis convention
/// (Omni3D: size = (W, H, L), H along the box's y axis, which points down like the camera's y).
geometry::Box3D worldBoxToCamera(const geometry::Box3D& upright_world_box, const Eigen::Isometry3d& T_camera_world);

/// The centre offset (m, world frame, on the ground) of one detection of `o` seen from `view`
/// (doc/simulator.md "Detection noise"): e = mu + sqrt(f) e_view + sqrt(1 - f) e_frame in the object
/// frame (Eq. shiftdist), e_view and e_frame zero-mean draws of `noise`'s shape, f =
/// persistent_variance_fraction; e_view is drawn from a generator seeded by (noise_seed, o.id,
/// viewpoint cell), so it repeats for similar viewpoints; e_frame comes from `rng`. Then the
/// deviation's component along the horizontal viewing ray is scaled by distance /
/// reference_distance_m (depth error of a monocular detector). At the reference distance the
/// offset has the model's mean and covariance (model::offsetCovariance()).
Eigen::Vector2d centreOffsetInWorld(const camera::PinholeCamera& view, const world::MapObject& o, const model::NoiseModel& noise,
                                    const DetectorParams& p, std::uint64_t noise_seed, Rng& rng);

/// A detection of object `o` (true class `class_id` of `num_classes`): with probability
/// detection_probability; centre = c_o + centreOffsetInWorld(), height, size and yaw perturbed;
/// sometimes a wrong label. nullopt when missed or scored below min_confidence.
std::optional<obs::Detection3D> detectObject(const camera::PinholeCamera& view, const world::MapObject& o,
                                             const model::NoiseModel& noise, std::size_t num_classes,
                                             const DetectorParams& p, Rng& rng, std::uint64_t noise_seed = 0);

/// A phantom box of a random class at a random free spot in the camera's view (line of sight
/// through `walls`), scored like a false detection; nullopt when no spot was found quickly.
std::optional<obs::Detection3D> phantomDetection(const camera::PinholeCamera& view, const Raster& walls,
                                                 const std::vector<std::string>& class_names,
                                                 const FalsePositiveParams& fp, const DetectorParams& p, Rng& rng);

}  // namespace simp::sim
