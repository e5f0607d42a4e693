#pragma once
/// \file DisplacedCopies.h
/// Map update (MapUpdate.h): which new objects of this session may be an earlier object displaced.
/// Such a new object must not hide the earlier one in I_active: a move of 0.3-0.7 m whose new place
/// stands between the camera and the old place otherwise leaves the old object occluded, so never
/// expected, never missed, never paired (doc/mapping.md "Map update across sessions").

#include <simp/world/ObjectMapData.h>

#include <cstdint>
#include <vector>

namespace simp::mapping {

/// Per object of `map` (same order): for an earlier object (id < first_new_id), the indices
/// (sorted) of the new objects (id >= first_new_id) of its class whose planar centre lies within
/// `max_distance_m` of its own (update_unhide_max_distance_m: the place it may have moved to);
/// empty for the new objects. The `unhidden_by` relation of camera::ZBufferParams.
std::vector<std::vector<int>> displacedCopyCandidates(const world::ObjectMapData& map, std::int64_t first_new_id,
                                                      double max_distance_m);

}  // namespace simp::mapping
