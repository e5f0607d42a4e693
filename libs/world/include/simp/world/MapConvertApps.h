#pragma once
/// \file MapConvertApps.h
/// The logic of `simp-import-map` and `simp-export-map` (rawlog_tools/), testable in-process:
/// initialize() parses the command line, run() does the work and prints a summary.

#include <simp/world/SimpFormat.h>

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
    bool helpRequested() const { return help_; }
    static std::string usage();

    std::string simp_dir, out_dir, heights_ini;
    World result;  ///< the imported world (after run)

   private:
    bool help_ = false;
};

/// simp-export-map --world W --out D
class ExportMapApp {
   public:
    void initialize(int argc, const char* const* argv);
    int run(std::ostream& out);
    bool helpRequested() const { return help_; }
    static std::string usage();

    std::string world_dir, out_dir;

   private:
    bool help_ = false;
};

/// Objects per class, one "  <class>: <count>" line each, classes without objects omitted.
std::string describeObjectCounts(const ObjectMapData& data);

}  // namespace simp::world
