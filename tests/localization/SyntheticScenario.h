#pragma once
/// \file SyntheticScenario.h
/// A small world and a short sequence generated in the tests: a 14 m x 9 m floor plan with
/// four rooms, 20 objects of 8 classes, a 4-camera rig (360 deg) seeing them with detector
/// noise (centre 8 cm, size 10 %, yaw 0.1 rad), 15 % missed detections and false positives
/// (30 % of the camera frames), 3 % odometry noise. Written as a world directory and a real .rawlog.

#include <mrpt/math/TPose2D.h>
#include <simp/io/Tum.h>
#include <simp/world/World.h>

#include <cstdint>
#include <string>
#include <vector>

namespace simp::localization::test {

struct Scenario {
    world::World world;
    std::vector<io::StampedPose2D> groundtruth;  ///< robot pose per frame
    std::string world_dir, rawlog_path, rawlog_obs_only_path, groundtruth_path;
    double duration_s = 0;
};

/// The world: walls, 4 rooms, objects with per-class noise models (sigma 0.15 m, b = 2).
world::World makeWorld();

/// Builds the scenario and writes it under `dir` (world/, sequence.rawlog in the
/// actions + sensory frames format, sequence_obs.rawlog in the observation-only format,
/// groundtruth.tum). Deterministic for a given seed.
Scenario makeScenario(const std::string& dir, std::uint32_t seed);

}  // namespace simp::localization::test
