/// \file OctomapExportOptions.cpp
/// [octomap] keys of the OctoMap export (OctomapExport.h).

#include <mrpt/config/CConfigFileBase.h>
#include <simp/export3d/OctomapExport.h>
#include <simp/io/StrictIni.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace simp::export3d {

void OctomapExportOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) {
    MRPT_LOAD_CONFIG_VAR(resolution_m, double, source, section);
    MRPT_LOAD_CONFIG_VAR(floor_z_m, double, source, section);
    MRPT_LOAD_CONFIG_VAR(ceiling_height_m, double, source, section);
    MRPT_LOAD_CONFIG_VAR(mark_free_space, bool, source, section);
    door_class = source.read_string(section, "door_class", door_class);
    MRPT_LOAD_CONFIG_VAR(export_open_doors, bool, source, section);
    MRPT_LOAD_CONFIG_VAR(max_voxels, double, source, section);
    validate("[" + section + "]");
}

void OctomapExportOptions::dumpToTextStream(std::ostream& out) const {
    out << "\n----------- [simp::export3d::OctomapExportOptions] ------------\n\n";
    LOADABLEOPTS_DUMP_VAR(resolution_m, double);
    LOADABLEOPTS_DUMP_VAR(floor_z_m, double);
    LOADABLEOPTS_DUMP_VAR(ceiling_height_m, double);
    LOADABLEOPTS_DUMP_VAR(mark_free_space, bool);
    out << "door_class                              = " << door_class << "\n";
    LOADABLEOPTS_DUMP_VAR(export_open_doors, bool);
    LOADABLEOPTS_DUMP_VAR(max_voxels, double);
}

void OctomapExportOptions::validate(const std::string& where) const {
    const auto fail = [&](const std::string& what) { throw std::invalid_argument(where + " " + what); };
    if (!(resolution_m >= kMinResolution_m && resolution_m <= kMaxResolution_m))
        fail("resolution_m = " + std::to_string(resolution_m) + " must be in [" + std::to_string(kMinResolution_m) +
             ", " + std::to_string(kMaxResolution_m) + "] m");
    if (!std::isfinite(floor_z_m) || std::abs(floor_z_m) > 100) fail("floor_z_m must be a finite height within 100 m");
    if (!(ceiling_height_m > floor_z_m && ceiling_height_m - floor_z_m <= 100))
        fail("ceiling_height_m = " + std::to_string(ceiling_height_m) + " must be above floor_z_m (" +
             std::to_string(floor_z_m) + ") by at most 100 m");
    if (!(max_voxels >= 1 && max_voxels <= 1e9)) fail("max_voxels must be in [1, 1e9]");
    if (door_class.empty()) fail("door_class must not be empty");
}

OctomapExportOptions loadOctomapExportOptions(const std::string& ini_path) {
    if (!std::filesystem::is_regular_file(ini_path)) throw std::invalid_argument(ini_path + ": .ini file not found");
    // The strict policy of every app: syntax, value types, unknown keys and sections (doc/bad-input.md).
    const simp::io::StrictIni cfg(ini_path);
    OctomapExportOptions opt;
    cfg.loadChecked([&](const simp::io::StrictIni& c) { opt.loadFromConfigFile(c, "octomap"); });
    return opt;
}

}  // namespace simp::export3d
