#pragma once
/// \file OctomapExport.h
/// The world directory as a 3D metric-semantic OctoMap (doc/import-export.md "OctoMap export"):
/// occupied floor-plan cells extruded from floor_z_m to ceiling_height_m, closed doors and every
/// other object box voxelized, free floor-plan cells free from floor to ceiling, the rest unknown.
/// `.bt`: octomap::OcTree, binary (occupancy only); `.ot`: octomap::ColorOcTree with class colours.

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/maps/COctoMap.h>
#include <simp/io/OptionTable.h>
#include <simp/world/World.h>

#include <cstddef>
#include <string>

namespace simp::export3d {

/// Options of the export, section [octomap] of an .ini (keys = field names).
struct OctomapExportOptions : public mrpt::config::CLoadableOptions {
    double resolution_m = 0.05;      ///< voxel edge (m), in [kMinResolution_m, kMaxResolution_m]
    double floor_z_m = 0.0;          ///< height of the floor (m, world z)
    double ceiling_height_m = 2.5;   ///< walls are extruded up to this height (m, world z); > floor_z_m
    bool mark_free_space = true;     ///< free floor-plan cells -> free voxels up to the ceiling
    std::string door_class = "door"; ///< class name of doors
    /// false: a door whose footprint centre lies on a free floor-plan cell (an open door in its gap)
    /// is not exported, so the passage stays free; true: every door box is exported.
    bool export_open_doors = false;
    /// Refuse an export whose leaf-voxel estimate (before pruning) exceeds this count
    /// (about 100 bytes per voxel while building: the default bounds the memory to ~2 GB).
    double max_voxels = 2e7;

    static constexpr double kMinResolution_m = 0.01;
    static constexpr double kMaxResolution_m = 1.0;

    /// The declaration of every key (section [octomap]).
    static const io::OptionTable<OctomapExportOptions>& table();
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
    void dumpToTextStream(std::ostream& out) const override;
    /// \throw std::invalid_argument starting with `where` and naming the key of a value out of range.
    void validate(const std::string& where) const;
};

/// Reads [octomap] of `ini_path` (every key optional; an unknown key is an error).
/// \throw std::invalid_argument naming the file, section and key.
OctomapExportOptions loadOctomapExportOptions(const std::string& ini_path);

/// What an export wrote.
struct OctomapExportSummary {
    std::size_t wall_cells = 0;        ///< occupied floor-plan cells extruded
    std::size_t free_cells = 0;        ///< free floor-plan cells marked free (mark_free_space)
    std::size_t objects = 0;           ///< object boxes voxelized (closed doors included)
    std::size_t closed_doors = 0;      ///< doors exported (export_open_doors: all doors)
    std::size_t open_doors_skipped = 0;
    double estimated_voxels = 0;       ///< the estimate checked against max_voxels
    std::size_t occupied_leaves = 0;   ///< after pruning
    std::size_t free_leaves = 0;       ///< after pruning
    std::size_t bytes = 0;             ///< file size
};

/// Voxel count the export would set before pruning (the bound checked against max_voxels).
double estimateVoxels(const simp::world::World& world, const OctomapExportOptions& opt);

/// Writes the world to `path`: `.bt` (OcTree, binary) or `.ot` (ColorOcTree: walls grey, objects in
/// their class colour, simp::obs::classColorRgb by name, as in every figure). A voxel is occupied by a wall when its
/// centre lies in an occupied floor-plan cell (free-cell probability <= 0.35, i.e. occupancy >= 0.65, as
/// the world's floorplan.png), and by a box when its centre lies within half a voxel of the box
/// (boxes thinner than a voxel still appear; planners get a conservative map).
/// \throw std::invalid_argument on another extension, bad options or an estimate above max_voxels;
///        std::runtime_error naming the file when it cannot be written.
OctomapExportSummary writeWorldOctomap(const simp::world::World& world, const OctomapExportOptions& opt,
                                       const std::string& path);

/// An MRPT map of an exported `.bt` / `.ot` file (occupancy only): MRPT 2.5.8's COctoMap cannot read
/// an OctoMap file through its public API (COctoMapBase::getOctomap<>() needs the private Impl), so
/// every known voxel is set with COctoMap::updateVoxel (pruned leaves expanded to voxels; one update
/// each: occupied p = 0.7, free p = 0.4). For MRPT's viewers: getVisualization() -> a .3Dscene.
/// \throw std::invalid_argument naming the file when OctoMap cannot read it or it has more than
///        max_voxels known voxels.
mrpt::maps::COctoMap toMrptOctoMap(const std::string& path, double max_voxels = 2e7);

/// The --octomap step of simp-export-map (simp::world::ExportMapApp::octomap_writer): options from
/// [octomap] of `ini_path` (empty: defaults), `resolution_text` (--resolution, empty: keep) overriding
/// resolution_m; writes `path` and returns the lines to print.
/// \throw std::invalid_argument naming --resolution, the file or the key on bad input.
std::string exportOctomapCommand(const simp::world::World& world, const std::string& ini_path,
                                 const std::string& resolution_text, const std::string& path);

}  // namespace simp::export3d
