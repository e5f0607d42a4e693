#pragma once
/// \file SimpFormat.h
/// Import / export of the authors' map format (PRBonn/SIMP, `ncore/data/floor/GTMap/0`):
///   floor.config          JSON: semantic.classes, semantic.categories, rooms, roomSeg
///   global_variance.json  per object: category, uid, corners (4 px), mx, my, sx, sy, b
///   Map.yaml + Map.png    ROS map_server floor plan
///   roomseg.png           room id + 1 per pixel (0 = none)
///   class_noise.csv       per class: category,mx,my,sx,sy,b (px); empty fields = not modelled
/// doc/import-export.md states exactly how the authors' numbers are interpreted.

#include <simp/world/World.h>

#include <map>
#include <string>

namespace simp::world {

struct SimpImportOptions {
    /// Height (m) per class name, overriding defaultClassHeight(); keys may use '_' for ' '.
    std::map<std::string, double> class_height_m;
};

/// Reads section [class_heights] of an MRPT-style .ini: `<class name with '_' for ' '> = <m>`.
/// \throw std::runtime_error naming the file and key on a missing file or a value <= 0.
SimpImportOptions loadSimpImportOptions(const std::string& ini_path);

/// Reads the authors' format in `dir` into a World (objects become upright boxes).
/// \throw std::runtime_error naming the file and key on any bad input.
World importSimpMap(const std::string& dir, const SimpImportOptions& options = {});

/// Writes `world` in the authors' format into `dir` (created when missing): floor.config,
/// global_variance.json (+ .csv), Map.yaml + Map.png, roomseg.png, class_noise.csv,
/// category_meta.json.
/// \throw std::runtime_error naming the file when it cannot be written or a room id > 254.
void exportSimpMap(const World& world, const std::string& dir);

}  // namespace simp::world
