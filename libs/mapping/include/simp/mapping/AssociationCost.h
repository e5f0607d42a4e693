#pragma once
/// \file AssociationCost.h
/// The association cost of two objects (paper Eq. costfunc) and the merge of a prediction
/// into an object (the weighted centre / size / rotation update of Sec. "3D Semantic Map
/// Construction"). All boxes in the world frame, canonical upright (local z up).

#include <simp/geometry/Box3D.h>
#include <simp/model/ObjectDistribution.h>

namespace simp::mapping {

/// C(o1, o2) = (C_IoU + C_cen) / 2, C_IoU = 1 - IoU3D(o1, o2), C_cen = 1 - p_o1(c_o2 | l)
/// (Eq. costfunc). In [0, 1]. o1 is the reference (map / local object), o2 the prediction;
/// p_o1 is o1's detection-centre distribution (Eqs. perclassdist / shiftdist, built by
/// model::makeObjectDistribution for o1's box and the noise model that applies to it).
double associationCost(const geometry::Box3D& o1, const model::ObjectDistribution& p_o1, const geometry::Box3D& o2);

/// Among the 4 equivalent representations of an upright box (rotation by k * 90 deg about its
/// local z; W and L swapped for odd k) the one whose rotation is closest (Frobenius) to `reference`.
geometry::Box3D closestEquivalent(const geometry::Box3D& box, const Eigen::Matrix3d& reference);

/// The merge update: centre and size are the n_match-weighted averages, the rotation the
/// weighted mean projected on SO(3) by SVD (Moakher), after aligning `prediction` to
/// `object` with closestEquivalent(). Returns the new box of `object`.
geometry::Box3D mergeBoxes(const geometry::Box3D& object, double n_match_object, const geometry::Box3D& prediction,
                           double n_match_prediction);

}  // namespace simp::mapping
