#pragma once
/// \file NoiseFrame.h
/// The ground frame a noise model (NoiseModel) is expressed in, for a map object. One rule for
/// the simulator, the mapper and the sensor model (Eq. shiftdist: Sigma_o = R_o Sigma R_o^T).

#include <simp/geometry/Box3D.h>
#include <simp/world/MapObject.h>

namespace simp::world {

/// Frame of a CLASS noise model: y along the object's longer horizontal side, x across it
/// (the authors' data: a board's large spread is along its length whichever way it faces),
/// independent of which of the box's equivalent axis labellings the box uses. Returns its yaw (rad).
double classNoiseFrameYaw(const geometry::Box3D& box);

/// Frame of the noise model that applies to object `o`: an object's own noise (MapObject::noise,
/// e.g. imported per-object noise) is in the box's own frame (yaw of the box x axis); a class
/// noise model is in classNoiseFrameYaw(o.box).
double noiseFrameYawOf(const MapObject& o);

}  // namespace simp::world
