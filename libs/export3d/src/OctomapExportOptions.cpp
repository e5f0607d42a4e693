/// \file OctomapExportOptions.cpp
/// [octomap] keys of the OctoMap export (OctomapExport.h).

#include <mrpt/config/CConfigFileBase.h>
#include <simp/export3d/OctomapExport.h>
#include <simp/io/StrictIni.h>

#include <filesystem>
#include <stdexcept>

namespace simp::export3d {

const io::OptionTable<OctomapExportOptions>& OctomapExportOptions::table() {
    using O = OctomapExportOptions;
    using io::ValueRange;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("octomap")
            .number("resolution_m", &O::resolution_m, "m", ValueRange::between(kMinResolution_m, kMaxResolution_m), "voxel edge; `--resolution` overrides it")
            .number("floor_z_m", &O::floor_z_m, "m", ValueRange::between(-100, 100), "floor height (world z)")
            .number("ceiling_height_m", &O::ceiling_height_m, "m", ValueRange::finite(),
                    "wall top (world z); above `floor_z_m` by at most 100 m")
            .flag("mark_free_space", &O::mark_free_space, "free cells -> free voxels up to the ceiling")
            .custom(
                "door_class", "", "a class name", "class name of doors",
                [](O& o, const std::string& text, const std::string&) { o.door_class = text; },
                [](const O& o, int) { return o.door_class; }, [](const O& o) { return !o.door_class.empty(); })
            .flag("export_open_doors", &O::export_open_doors, "also export doors standing in an open gap (a free floor-plan cell)")
            .number("max_voxels", &O::max_voxels, "", ValueRange::between(1, 1e9), "refuse an export whose voxel estimate (known cells x layers + box volumes, before pruning) is larger")
            .rule("ceiling_height_m",
                  [](const O& o) { return o.ceiling_height_m > o.floor_z_m && o.ceiling_height_m - o.floor_z_m <= 100; },
                  "be above floor_z_m by at most 100 m");
    return t;
}

void OctomapExportOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) {
    table().load(source, section, *this);
}

void OctomapExportOptions::dumpToTextStream(std::ostream& out) const { table().dump(*this, out); }

void OctomapExportOptions::validate(const std::string& where) const {
    try {
        table().validate(*this);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(where + " " + e.what());
    }
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
