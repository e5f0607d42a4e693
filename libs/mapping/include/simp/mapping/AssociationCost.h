#pragma once
/// \file AssociationCost.h
/// The association cost of two objects (paper Eq. costfunc) and the merge of a prediction
/// into an object (the weighted centre / size / rotation update of Sec. "3D Semantic Map
/// Construction"). All boxes in the world frame, canonical upright (local z up).

#include <simp/geometry/Box3D.h>
#include <simp/world/NoiseModel.h>

namespace simp::mapping {

/// Yaw (rad) of the frame the class noise models are expressed in: y along the box's longer
/// horizontal side, x along the shorter one (the convention of the authors' global_variance.csv,
/// the same as the simulator's simp::sim::noiseFrameYaw); independent of which of the box's 4
/// equivalent upright frames `box` uses.
double noiseFrameYaw(const geometry::Box3D& box);

/// p_o1(c | l): the class noise density centred on object o1, evaluated at the point c,
/// unnormalized to [0, 1]: exp(-0.5 m^b) with m the Mahalanobis distance of
/// d = R(noiseFrameYaw(o1))^T (c - c_o1)_xy - mu in the noise frame on the ground
/// (Eq. perclassdist / shiftdist with the authors' exponent b).
double centerScore(const geometry::Box3D& o1, const world::NoiseModel& noise, const Eigen::Vector3d& c);

/// C(o1, o2) = (C_IoU + C_cen) / 2, C_IoU = 1 - IoU3D(o1, o2), C_cen = 1 - p_o1(c_o2 | l)
/// (Eq. costfunc). In [0, 1]. o1 is the reference (map / local object), o2 the prediction.
double associationCost(const geometry::Box3D& o1, const world::NoiseModel& noise_o1, const geometry::Box3D& o2);

/// Among the 4 equivalent representations of an upright box (rotation by k * 90 deg about its
/// local z; W and L swapped for odd k) the one whose rotation is closest (Frobenius) to `reference`.
geometry::Box3D closestEquivalent(const geometry::Box3D& box, const Eigen::Matrix3d& reference);

/// The merge update: centre and size are the n_match-weighted averages, the rotation the
/// weighted mean projected on SO(3) by SVD (Moakher), after aligning `prediction` to
/// `object` with closestEquivalent(). Returns the new box of `object`.
geometry::Box3D mergeBoxes(const geometry::Box3D& object, double n_match_object, const geometry::Box3D& prediction,
                           double n_match_prediction);

}  // namespace simp::mapping
