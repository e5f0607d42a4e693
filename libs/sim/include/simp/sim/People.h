#pragma once
/// \file People.h
/// People walking from room to room: dynamic objects of class "person" that are never in the map.

#include <mrpt/math/TPose2D.h>
#include <simp/sim/Random.h>
#include <simp/sim/Raster.h>
#include <simp/sim/SensorParams.h>
#include <simp/world/World.h>

#include <vector>

namespace simp::sim {

/// Planar poses (m, rad; heading = walking direction) of `p.count` people at each of `times_s`
/// (result[person][k]). They walk shortest paths between random room goals at a constant speed
/// drawn per leg. No person when the map has no free space.
std::vector<std::vector<mrpt::math::TPose2D>> simulatePeople(const Raster& obstacles, const world::RoomMap& rooms,
                                                             const PeopleParams& p, const std::vector<double>& times_s,
                                                             Rng& rng);

}  // namespace simp::sim
