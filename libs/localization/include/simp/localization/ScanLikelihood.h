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
#include <simp/world/ObjectMapData.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

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

    /// out_log[i] = weight x log p(scan | poses[i]) for i < n (MRPT's likelihood field; scan.sensorPose applied).
    /// Not thread-safe (the grid and its likelihood cache are built on use).
    void logLikelihoods(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D* poses, std::size_t n,
                        double* out_log) const;

    const LidarModelOptions& options() const { return m_opts; }
    /// Objects drawn into the scan grid at the last scan's height (0 without an object map).
    std::size_t objectsInGrid() const { return m_objects_drawn; }

   private:
    /// The grid for a scan plane at height_m (rebuilt only when the height changes).
    mrpt::maps::COccupancyGridMap2D& gridAt(double height_m) const;

    LidarModelOptions m_opts;
    mrpt::maps::COccupancyGridMap2D m_floorplan;
    std::optional<world::ObjectMapData> m_objects;
    mutable std::unique_ptr<mrpt::maps::COccupancyGridMap2D> m_grid;
    mutable double m_grid_height_m = 0;
    mutable std::size_t m_objects_drawn = 0;
};

/// The last CObservation2DRangeScan of a sensory frame (nullptr: none).
mrpt::obs::CObservation2DRangeScan::Ptr lastScan(const mrpt::obs::CSensoryFrame& sf);

}  // namespace simp::localization
