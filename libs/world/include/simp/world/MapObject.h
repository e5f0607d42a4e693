#pragma once
/// \file MapObject.h
/// One object of the object map (paper Eq. objdef): class, 3D box in the world frame and
/// the mapping counters.

#include <simp/geometry/Box3D.h>
#include <simp/model/NoiseFrame.h>
#include <simp/model/NoiseModel.h>

#include <cstdint>
#include <optional>

namespace simp::world {

struct MapObject {
    std::int64_t id = 0;        ///< unique within a map
    int class_id = 0;           ///< index into ObjectMapData::class_names
    geometry::Box3D box;        ///< world frame (z up); canonical upright: local z = up, size = (x, y, height)
    int n_match = 1;            ///< detections merged into it
    int n_skip = 0;             ///< times it was active but not matched
    int room_id = 0;            ///< room id of its centre (0 = none)
    std::optional<model::NoiseModel> noise;  ///< per-object noise (authors' global_variance.json); else the class's

    /// Which noise model applies (ObjectMapData::noiseOf), hence its frame (model::noiseFrameYaw).
    model::NoiseSource noiseSource() const { return noise ? model::NoiseSource::Object : model::NoiseSource::Class; }
};

}  // namespace simp::world
