/// simp-map: metric-semantic object map construction (doc/mapping.md).
#include <simp/mapping/MapApp.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::mapping::MapApp app;
        if (!app.initialize(argc, argv)) return 0;
        app.run();
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-map: error: " << e.what() << "\n";
        return 1;
    }
}
