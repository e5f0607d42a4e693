#pragma once
/// \file WorldMultiMap.h
/// A world directory as MRPT's multi-map: the floor-plan COccupancyGridMap2D beside the
/// CObjectMap, the arrangement MRPT's particle filters and map tools expect.

#include <mrpt/maps/CMultiMetricMap.h>
#include <simp/maps/CObjectMap.h>
#include <simp/world/World.h>

#include <string>

namespace simp::maps {

/// Maps [0] = the floor plan (a copy of world.floorplan), [1] = the object map with `likelihood`.
/// \throw std::invalid_argument from CObjectMap::setData (e.g. a class without a noise model).
mrpt::maps::CMultiMetricMap::Ptr makeMultiMetricMap(const world::World& world,
                                                    const CObjectMap::TLikelihoodOptions& likelihood = {});

/// Same for a world directory on disk (world::loadWorld: errors name the file).
mrpt::maps::CMultiMetricMap::Ptr loadMultiMetricMap(const std::string& world_dir,
                                                    const CObjectMap::TLikelihoodOptions& likelihood = {});

}  // namespace simp::maps
