#pragma once
/// \file MapConvertApps.h
/// The logic of `simp-import-map` and `simp-export-map` (rawlog_tools/), testable in-process:
/// initialize() parses the command line, run() does the work and prints a summary.

#include <simp/io/CommandLine.h>
#include <simp/world/SimpFormat.h>

#include <functional>
#include <ostream>
#include <string>

namespace simp::world {

/// simp-import-map --simp-dir D --out W [--heights INI]
class ImportMapApp {
   public:
    /// \throw std::invalid_argument on an unknown option or a missing value/required option.
    void initialize(int argc, const char* const* argv);
    /// Imports, writes the world directory, prints what was imported; returns the exit code.
    int run(std::ostream& out);
    static std::string usage();
    static io::CommandLine commandLine();  ///< the declared options

    std::string simp_dir, out_dir, heights_ini;
    World result;  ///< the imported world (after run)

   private:
    bool help_ = false;
};

/// simp-export-map --world W [--out D] [--gridmap F.gridmap] [--octomap F.bt|F.ot [--resolution M] [--config INI]]
/// (at least one of --out, --gridmap, --octomap).
class ExportMapApp {
   public:
    void initialize(int argc, const char* const* argv);
    int run(std::ostream& out);
    static std::string usage();
    static io::CommandLine commandLine();  ///< the declared options

    std::string world_dir, out_dir, gridmap_path, octomap_path, config_ini, resolution;

    /// Writes the OctoMap (libs/export3d, which this library cannot depend on: the object colours come
    /// from libs/maps): world, .ini path (may be empty), --resolution text (may be empty), output
    /// path; returns the summary lines to print. simp-export-map's main() sets it; --octomap without
    /// it is an error.
    std::function<std::string(const World&, const std::string&, const std::string&, const std::string&)>
        octomap_writer;

   private:
    bool help_ = false;
};

/// Objects per class, one "  <class>: <count>" line each, classes without objects omitted.
std::string describeObjectCounts(const ObjectMapData& data);

}  // namespace simp::world
