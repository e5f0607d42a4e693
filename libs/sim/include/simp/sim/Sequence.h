#pragma once
/// \file Sequence.h
/// `simp-sim sequence`: a robot with odometry and a multi-camera 3D object detector driving
/// through a (possibly changed) world, written as an MRPT rawlog + TUM ground truth + world dir.

#include <simp/io/Tum.h>
#include <simp/sim/SimParams.h>
#include <simp/world/World.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace simp::sim {

/// Counts of what a simulated sequence contains.
struct SequenceSummary {
    std::size_t steps = 0;             ///< odometry steps (action + sensory frame pairs)
    std::size_t camera_frames = 0;     ///< CObservationObjects3D written (all cameras)
    std::size_t true_detections = 0;  ///< detections of real map objects (right or wrong label)
    std::size_t person_detections = 0;
    std::size_t phantom_detections = 0;
    std::size_t scans = 0;             ///< CObservation2DRangeScan written ([lidar] enabled)
    ChangeSummary changes;
    double path_length_m = 0;          ///< driven path (m; the teleport of a kidnap not included)
    std::optional<KidnapEvent> kidnap; ///< the teleport, when params.kidnap_at_s >= 0
    std::optional<CoverageProgress> coverage;  ///< a coverage run's progress ([trajectory] visit_order)
};

/// Simulates one sequence in `map_world` (changed by params.changes first) and writes
/// `out_dir`/sequence.rawlog, groundtruth.tum, world/, changes.json, overview.png and, with
/// params.kidnap_at_s >= 0, kidnap.json (a stale one is removed otherwise). Every random choice
/// comes from `seed`; the same inputs give byte-identical files (simulated time from
/// params.epoch_s, never the wall clock). The kidnap draws from a stream split off after all
/// others, so without it every file is as before the kidnap existed.
/// `map_world_dir` (optional): the directory `map_world` was read from, named in changes.json as
/// the world its `before` ids belong to.
/// \throw std::runtime_error naming the file that cannot be written or the map that has no room
/// for the robot; std::invalid_argument for kidnap_at_s beyond the duration.
SequenceSummary simulateSequence(const world::World& map_world, const SimParams& params, std::uint64_t seed,
                                 const std::string& out_dir, const std::string& map_world_dir = {});

/// Draws the world (floor plan, object footprints coloured by class) and the true `trajectory`
/// (green, circle at the start) to a PNG with a scale bar and a legend (simp::eval::drawTrajectoryMap).
/// With jump_step > 0 (a kidnap) the segment into pose jump_step is not drawn; a blue ring marks
/// where the robot was lifted, an orange dot where it was put down.
void writeOverviewPng(const world::World& world, const std::vector<io::StampedPose2D>& trajectory,
                      const std::string& png_path, std::size_t jump_step = 0);

}  // namespace simp::sim
