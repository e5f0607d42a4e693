/// simp-stats: per-class detection noise model (paper Sec. "Statistical Analysis").
/// The logic lives in simp::stats::StatsApp (libs/stats); usage: simp-stats --help.
#include <simp/stats/StatsApp.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::stats::StatsApp app;
        if (!app.initialize(argc, argv, std::cout)) return 0;
        return app.run(std::cout);
    } catch (const std::exception& e) {
        std::cerr << "simp-stats: error: " << e.what() << "\n";
        return 1;
    }
}
