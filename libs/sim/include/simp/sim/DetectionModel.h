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
world::NoiseModel noiseFor(const world::ObjectMapData& map, const world::MapObject& o, const DetectorParams& p);

/// An upright world box (local z up) as a camera-frame box with the detector's axis convention
/// (Omni3D: size = (W, H, L), H along the box's y axis, which points down like the camera's y).
geometry::Box3D worldBoxToCamera(const geometry::Box3D& upright_world_box, const Eigen::Isometry3d& T_camera_world);

/// A detection of object `o` (true class `class_id` of `num_classes`): with probability
/// detection_probability; centre = c_o + R_o * offset with offset ~ `noise` (object frame on the
/// ground, Eq. shiftdist), height, size and yaw perturbed; sometimes a wrong label. nullopt when
/// missed or scored below min_confidence.
std::optional<obs::Detection3D> detectObject(const CameraView& view, const world::MapObject& o,
                                             const world::NoiseModel& noise, std::size_t num_classes,
                                             const DetectorParams& p, Rng& rng);

/// A phantom box of a random class at a random free spot in the camera's view (line of sight
/// through `walls`), scored like a false detection; nullopt when no spot was found quickly.
std::optional<obs::Detection3D> phantomDetection(const CameraView& view, const Raster& walls,
                                                 const std::vector<std::string>& class_names,
                                                 const FalsePositiveParams& fp, const DetectorParams& p, Rng& rng);

}  // namespace simp::sim
