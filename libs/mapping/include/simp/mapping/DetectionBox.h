#pragma once
/// \file DetectionBox.h
/// The object frame of a detected box: from the detector's box convention to the map's.

#include <simp/geometry/Box3D.h>

namespace simp::mapping {

/// A detection's box (already transformed to the world, still in the detector's axis convention:
/// Omni3D / CObservationObjects3D, size = (W, H, L), local x = W, local y = H pointing down,
/// local z = L) as an upright map box whose local frame is the object frame of the class noise
/// models (simp::model::NoiseModel, Eq. shiftdist): x = the detector's x (W), y = the detector's z
/// (L), z = up (H). Without this re-labelling geometry::canonicalizeUpright() alone would pick
/// x = L, y = -W, i.e. the noise model's axes swapped. The result is canonicalized
/// (geometry::canonicalizeUpright) so a tilted box still gets its most vertical axis as z.
geometry::Box3D objectBoxFromDetection(const geometry::Box3D& detector_box_in_world);

}  // namespace simp::mapping
