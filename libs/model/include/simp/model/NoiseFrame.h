#pragma once
/// \file NoiseFrame.h
/// The ground frame a noise model (NoiseModel) is expressed in, for a map object: R_o of
/// Eq. shiftdist (Sigma_o = R_o Sigma R_o^T). The one rule of the simulator, the mapper, the
/// sensor model and the statistics.

#include <simp/geometry/Box3D.h>

namespace simp::model {

/// Which noise model applies to an object: its class's, or its own (MapObject::noise, e.g. the
/// authors' per-object global_variance.json). The two are expressed in different frames.
enum class NoiseSource { Class, Object };

/// Frame of a CLASS noise model: y along the object's longer horizontal side, x across it
/// (the authors' data: a board's large spread is along its length whichever way it faces),
/// independent of which of the box's equivalent axis labellings the box uses. Returns its yaw (rad).
double classNoiseFrameYaw(const geometry::Box3D& box);

/// Yaw (rad, world) of the frame of the noise model from `source` for an object with box `box`:
/// an object's own noise is in the box's own frame (yaw of the box x axis), a class noise model
/// in classNoiseFrameYaw(box).
double noiseFrameYaw(const geometry::Box3D& box, NoiseSource source);

}  // namespace simp::model
