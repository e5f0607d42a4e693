#pragma once
/// \file DetectionPoseSampler.h
/// Sensor resetting (Lenser & Veloso, ICRA 2000; not in the paper): robot poses drawn where a
/// current detection fits a map object of its class, so that a filter that lost the pose (or a
/// robot carried elsewhere) gets hypotheses where the evidence is, instead of only uniform ones.

#include <mrpt/math/TPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/FrameLikelihood.h>
#include <simp/localization/FreeSpace.h>
#include <simp/maps/CObjectMap.h>

#include <vector>

namespace simp::localization {

struct DetectionPoseSamplerParams {
    double position_std_m = 0.25;   ///< spread of a drawn position about the exact fit (m)
    double heading_std_rad = 0.15;  ///< spread of a drawn heading (rad)
    /// Footprints whose sides differ by less than this ratio (short / long >= it) are treated as
    /// square: their heading is ambiguous by pi/2, not only by pi.
    double square_ratio = 0.75;
};

class DetectionPoseSampler {
   public:
    DetectionPoseSampler(const maps::CObjectMap& map, const FreeSpace& free_space,
                         const DetectionPoseSamplerParams& params = {});

    /** Up to `count` poses in free space: each picks a used detection of `observations` (camera
     * pose in the robot frame), a map object of its class and one of the box's symmetric
     * headings, and puts the robot where the detection's box lands on the object's expected
     * detection centre (Eq. shiftdist mean; the box centre for the baselines), with Gaussian
     * spread. Fewer (possibly none) when no detection is usable or too few draws are free. */
    std::vector<mrpt::math::TPose2D> sample(const std::vector<WeightedObservation>& observations, std::size_t count,
                                            mrpt::random::CRandomGenerator& rng) const;

   private:
    const maps::CObjectMap& m_map;
    const FreeSpace& m_free;
    DetectionPoseSamplerParams m_params;
};

}  // namespace simp::localization
