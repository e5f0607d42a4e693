/// simp-pf-localization: MRPT 2.5's pf-localization with the project's plugins linked in.
/// The program is the body of MRPT's apps/pf-localization/pf_localization_main.cpp around the same
/// library class, mrpt::apps::MonteCarloLocalization_Rawlog: `simp-pf-localization CONFIG.ini [RAWLOG]`
/// behaves as `LD_PRELOAD=libsimp_obs.so:libsimp_maps.so:libsimp_mapping.so pf-localization CONFIG.ini [RAWLOG]`
/// (doc/plugin.md "pf-localization"), except that it exits without waiting for a key on errors.
#include <mrpt/apps/MonteCarloLocalization_App.h>
#include <mrpt/core/exceptions.h>
#include <simp/io/CommandLine.h>
#include <simp/mapping/registerAllClasses.h>
#include <simp/maps/registerAllClasses.h>
#include <simp/obs/registerAllClasses.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

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
    simp::io::CommandLine args("simp-pf-localization",
                               "MRPT's pf-localization (mrpt::apps::MonteCarloLocalization_Rawlog) with the project's plugins\n"
                               "(libsimp_obs, libsimp_maps, libsimp_mapping) linked: no LD_PRELOAD needed. Configuration:\n"
                               "config_ini/pf-localization.ini; see doc/plugin.md.");
    args.positional("CONFIG.ini", "the configuration (MRPT's pf-localization .ini)", true)
        .positional("DATASET.rawlog", "the rawlog (overrides the .ini's rawlog_file)", false);
    try {
        if (!args.parse(argc, argv, std::cout)) return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-pf-localization: error: " << e.what() << "\n";
        return 1;
    }
    const std::string config = args.positionals().front();
    if (!std::ifstream(config)) {
        std::cerr << "simp-pf-localization: error: " << config << ": configuration file not found\n";
        return 1;
    }
    if (const std::string unset = unsetEnvironmentVariables(config); !unset.empty()) {
        std::cerr << "simp-pf-localization: error: " << config << " uses $env{...} of unset environment variables: "
                  << unset << " (doc/plugin.md)\n";
        return 1;
    }
    // MRPT's own command line: the program, CONFIG.ini [, DATASET.rawlog]
    std::vector<std::string> mrpt_args{argc > 0 ? argv[0] : "simp-pf-localization"};
    mrpt_args.insert(mrpt_args.end(), args.positionals().begin(), args.positionals().end());
    std::vector<const char*> mrpt_argv;
    for (const auto& a : mrpt_args) mrpt_argv.push_back(a.c_str());
    try {
        simp::obs::registerAllClasses();
        simp::maps::registerAllClasses();
        simp::mapping::registerAllClasses();
        mrpt::apps::MonteCarloLocalization_Rawlog app;
        app.initialize(static_cast<int>(mrpt_argv.size()), mrpt_argv.data());
        app.run();
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-pf-localization: error: " << messagesOf(mrpt::exception_to_str(e)) << "\n";
        return 1;
    }
}
