/// simp-pf-localization: MRPT 2.5's pf-localization with the project's plugins linked in.
/// The program is the body of MRPT's apps/pf-localization/pf_localization_main.cpp around the same
/// library class, mrpt::apps::MonteCarloLocalization_Rawlog: `simp-pf-localization CONFIG.ini [RAWLOG]`
/// behaves as `LD_PRELOAD=libsimp_obs.so:libsimp_maps.so:libsimp_mapping.so pf-localization CONFIG.ini [RAWLOG]`
/// (doc/plugin.md "pf-localization"), except that it exits without waiting for a key on errors.
#include <mrpt/apps/MonteCarloLocalization_App.h>
#include <mrpt/core/exceptions.h>
#include <simp/mapping/registerAllClasses.h>
#include <simp/maps/registerAllClasses.h>
#include <simp/obs/registerAllClasses.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>

namespace {

/// The `$env{NAME}` of the .ini that are not set: MRPT would silently substitute "" (paths such as
/// "/sequence.rawlog" then fail far from the cause).
std::string unsetEnvironmentVariables(const std::string& ini_path) {
    std::ifstream f(ini_path);
    std::string line, missing;
    const std::regex env(R"(\$env\{([A-Za-z_][A-Za-z0-9_]*)\})");
    while (std::getline(f, line)) {
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#' || line[first] == ';') continue;  // comments
        for (std::sregex_iterator it(line.begin(), line.end(), env), end; it != end; ++it) {
            const std::string name = (*it)[1];
            if (!std::getenv(name.c_str()) && (" " + missing + ",").find(" " + name + ",") == std::string::npos)
                missing += (missing.empty() ? "" : ", ") + name;
        }
    }
    return missing;
}

/// MRPT's exception text reduced to its "Message:" lines (no call stacks).
std::string messagesOf(const std::string& text) {
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line))
        if (line.rfind("Message:", 0) == 0) out += (out.empty() ? "" : "\n") + line.substr(9);
    return out.empty() ? text : out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        std::cout << "usage: simp-pf-localization CONFIG.ini [DATASET.rawlog]\n"
                     "  MRPT's pf-localization (mrpt::apps::MonteCarloLocalization_Rawlog) with the project's\n"
                     "  plugins (libsimp_obs, libsimp_maps, libsimp_mapping) linked: no LD_PRELOAD needed. Configuration:\n"
                     "  config_ini/pf-localization.ini; see doc/plugin.md.\n";
        return 0;
    }
    if (argc >= 2) {
        if (!std::ifstream(argv[1])) {
            std::cerr << "simp-pf-localization: error: " << argv[1] << ": configuration file not found\n";
            return 1;
        }
        if (const std::string unset = unsetEnvironmentVariables(argv[1]); !unset.empty()) {
            std::cerr << "simp-pf-localization: error: " << argv[1] << " uses $env{...} of unset environment variables: "
                      << unset << " (doc/plugin.md)\n";
            return 1;
        }
    }
    try {
        simp::obs::registerAllClasses();
        simp::maps::registerAllClasses();
        simp::mapping::registerAllClasses();
        mrpt::apps::MonteCarloLocalization_Rawlog app;
        app.initialize(argc, argv);
        app.run();
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-pf-localization: error: " << messagesOf(mrpt::exception_to_str(e)) << "\n";
        return 1;
    }
}
