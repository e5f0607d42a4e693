/// simp-pf-localization: MRPT 2.5's pf-localization with the project's plugins linked in.
/// The program is the body of MRPT's apps/pf-localization/pf_localization_main.cpp around the same
/// library class, mrpt::apps::MonteCarloLocalization_Rawlog: `simp-pf-localization CONFIG.ini [RAWLOG]`
/// behaves as `LD_PRELOAD=libsimp_obs.so:libsimp_maps.so pf-localization CONFIG.ini [RAWLOG]`
/// (doc/plugin.md "pf-localization"), except that it exits without waiting for a key on errors.
#include <mrpt/apps/MonteCarloLocalization_App.h>
#include <mrpt/core/exceptions.h>
#include <simp/maps/registerAllClasses.h>
#include <simp/obs/registerAllClasses.h>

#include <cstring>
#include <iostream>

int main(int argc, char** argv) {
    if (argc >= 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        std::cout << "usage: simp-pf-localization CONFIG.ini [DATASET.rawlog]\n"
                     "  MRPT's pf-localization (mrpt::apps::MonteCarloLocalization_Rawlog) with the project's\n"
                     "  plugins (libsimp_obs, libsimp_maps) linked: no LD_PRELOAD needed. Configuration:\n"
                     "  config_ini/pf-localization.ini; see doc/plugin.md.\n";
        return 0;
    }
    try {
        simp::obs::registerAllClasses();
        simp::maps::registerAllClasses();
        mrpt::apps::MonteCarloLocalization_Rawlog app;
        app.initialize(argc, argv);
        app.run();
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-pf-localization: error: " << mrpt::exception_to_str(e) << "\n";
        return 1;
    }
}
