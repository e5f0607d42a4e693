#pragma once
/// \file DetectionPoseSampler.h
/// Sensor resetting (Lenser & Veloso, ICRA 2000; not in the paper): robot poses drawn where a
/// current detection fits a map object of its class, so that a filter that lost the pose (or a
/// robot carried elsewhere) gets hypotheses where the evidence is, instead of only uniform ones.

#include <mrpt/math/TPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/FrameLikelihood.h>
#include <simp/localization/FreeSpace.h>
#include <simp/localization/LocalizationState.h>
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

    /** Every exact fit (no spread): one pose per (used detection, map object of its class, box
     * symmetry) whose position is in free space, at most `max_count` (the first ones, in the order
     * of the detections and the map's objects). */
    std::vector<mrpt::math::TPose2D> candidates(const std::vector<WeightedObservation>& observations,
                                                std::size_t max_count) const;

    /// Pairs of detections (placed in one frame F, e.g. the odometry frame) against pairs of map
    /// objects of their classes.
    struct PairFitParams {
        double min_separation_m = 1.0;  ///< detection pairs closer than this (m) are not used
        double tolerance_m = 0.4;       ///< |map distance - detection distance| allowed (m)
        double merge_radius_m = 0.5;    ///< detections of one class this close are one object first
    };
    /** Every rigid fit of a pair of detections on a pair of map objects of their classes at about
     * the same distance: the pose of frame F in the world (F (+) detection = object). The heading
     * comes from the pair's geometry, not from a box's yaw, so it is as good as the positions over
     * the pair's separation; pairs farther apart first, at most `max_count`. */
    std::vector<mrpt::math::TPose2D> pairFits(const std::vector<FitWindow::Placed>& placed, const PairFitParams& params,
                                              std::size_t max_count) const;

    const FreeSpace& freeSpace() const { return m_free; }

   private:
    struct Usable {
        Eigen::Vector2d centre_robot_m;
        double yaw_robot_rad = 0;
        int symmetries = 2;  ///< 4 for square footprints (heading ambiguous by pi/2), else 2
        int map_class = -1;
    };
    std::vector<Usable> usableDetections(const std::vector<WeightedObservation>& observations) const;
    /// Robot pose that puts detection d on map object o, turned by `turn` of d's symmetries, with
    /// the given position and heading offsets.
    mrpt::math::TPose2D fit(const Usable& d, std::size_t o, int turn, double dphi, double dx, double dy) const;

    const maps::CObjectMap& m_map;
    const FreeSpace& m_free;
    DetectionPoseSamplerParams m_params;
    std::vector<std::vector<std::size_t>> m_by_class;  ///< map objects per class id
    std::vector<Eigen::Vector2d> m_expected_centre_m;  ///< per object: where its detections land (Eq. shiftdist mean)
};

}  // namespace simp::localization
