#pragma once
/// \file ScanLikelihood.h
/// The LiDAR sensor model of `simp-localize --method lidar|simp+lidar`: a 2D scan weighed against the
/// floor-plan grid alone with MRPT's likelihood field (COccupancyGridMap2D, lmLikelihoodField_Thrun),
/// the model plain LiDAR MCL uses (doc/lidar.md). [LidarModel] of the localization .ini. Given an object
/// map, its objects that span the scan plane are walls too (`simp+lidar`: the map is floor plan + boxes).

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <simp/io/OptionTable.h>
#include <simp/camera/WallDistance.h>
#include <simp/world/ObjectMapData.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace simp::localization {

/// [LidarModel]: every field is the .ini key of the same name.
struct LidarModelOptions {
    /// Exponent of the scan likelihood: log w += weight x log p(scan | x). With `simp+lidar` it is the
    /// scan's weight relative to the object model (whose exponent is 1); with `lidar` it tempers the
    /// sum over beams, which treats the beams as independent and is far too sure of itself.
    double weight = 0.05;
    int decimation = 10;         ///< every n-th beam is weighed (1081 -> 109), COccupancyGridMap2D LF_decimation
    double sigma_m = 0.15;       ///< std of a hit around the nearest wall (m), LF_stdHit
    double z_hit = 0.9;          ///< weight of the hit model, LF_zHit
    double z_random = 0.1;       ///< weight of random returns (people, furniture not in the plan), LF_zRandom
    double max_range_m = 15.0;   ///< beams beyond are not weighed (m), LF_maxRange
    double max_corr_distance_m = 0.3;  ///< distance to the nearest wall is capped here (m), LF_maxCorrsDistance
    /// Returns shorter than this (m) are not weighed: they end inside the robot's own footprint, so they
    /// come from a body touching or crossing the robot (a person), never from the map. Without it a scan
    /// blocked at the sensor (every range ~0) is best explained by a pose inside a wall.
    double min_range_m = 0.3;
    /// Beam skipping (the AMCL rule): a return counts as explained at a particle when its end lies within
    /// beam_skip_distance_m of an obstacle of the scan grid; a return explained at fewer than
    /// beam_skip_threshold of the particles is not weighed (a person, a moved or new object, a closed
    /// door: whatever the map lacks pulls the pose toward wherever it happens to land on a wall). When
    /// more than beam_skip_max_fraction of the returns would go, none does (the set is spread or wrong,
    /// and the scan is what can tell). beam_skip_threshold = 0: off.
    double beam_skip_distance_m = 0.3;
    double beam_skip_threshold = 0.3;
    double beam_skip_max_fraction = 0.9;
    /// `simp+lidar`: the map's objects spanning the scan plane (the scan's sensorPose z) are obstacles
    /// of the scan grid; `lidar` never uses them (plain LiDAR MCL on the floor plan).
    bool map_objects = true;

    /// The declaration of every key (section [LidarModel]).
    static const io::OptionTable<LidarModelOptions>& table();
    /// Reads [section]; absent keys keep the defaults. \throw std::invalid_argument naming section and key.
    void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section = "LidarModel");
};

class ScanLikelihood {
   public:
    /// Copies `floorplan` (the map given to the localizer: walls only) and, when given, `objects`:
    /// those spanning the scan plane are drawn into the grid (at the height of the first scan, again
    /// when a scan comes from another height).
    ScanLikelihood(const mrpt::maps::COccupancyGridMap2D& floorplan, const LidarModelOptions& options,
                   const world::ObjectMapData* objects = nullptr);

    /// out_log[i] = weight x log p(scan | poses[i]) for i < n (MRPT's likelihood field; scan.sensorPose applied;
    /// returns shorter than min_range_m and, with skip_unexplained, the beams skipped for this set of poses
    /// left out; none left: every out_log[i] = 0). Not thread-safe (the grid and its caches are built on use).
    void logLikelihoods(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D* poses, std::size_t n,
                        double* out_log, bool skip_unexplained = true) const;

    const LidarModelOptions& options() const { return m_opts; }
    /// Objects drawn into the scan grid at the last scan's height (0 without an object map).
    std::size_t objectsInGrid() const { return m_objects_drawn; }

    /// Returns that will be weighed for this set of poses: valid, not shorter than min_range_m, not skipped.
    std::vector<char> usableReturns(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D* poses,
                                    std::size_t n, bool skip_unexplained = true) const;
    /// Number of returns the last logLikelihoods() call left out by beam skipping.
    std::size_t lastSkipped() const { return m_last_skipped; }

   private:
    /// Marks the returns explained at fewer than beam_skip_threshold of `poses` as unusable (unless too many).
    void skipUnexplained(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D* poses,
                         std::size_t n, std::vector<char>& usable) const;

    /// The grid for a scan plane at height_m (rebuilt only when the height changes).
    mrpt::maps::COccupancyGridMap2D& gridAt(double height_m) const;

    LidarModelOptions m_opts;
    mrpt::maps::COccupancyGridMap2D m_floorplan;
    std::optional<world::ObjectMapData> m_objects;
    mutable std::unique_ptr<mrpt::maps::COccupancyGridMap2D> m_grid;
    mutable double m_grid_height_m = 0;
    mutable std::size_t m_objects_drawn = 0;
    mutable camera::WallDistance m_wall_distance;  ///< of m_grid's obstacles (beam skipping)
    mutable std::size_t m_last_skipped = 0;
};

/// The last CObservation2DRangeScan of a sensory frame (nullptr: none).
mrpt::obs::CObservation2DRangeScan::Ptr lastScan(const mrpt::obs::CSensoryFrame& sf);

}  // namespace simp::localization
