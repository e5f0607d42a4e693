/// simp-export-map: a world directory -> the authors' map format (for their ROS tools).
/// The logic lives in simp::world::ExportMapApp (libs/world); usage: simp-export-map --help.
#include <simp/world/MapConvertApps.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::world::ExportMapApp app;
        app.initialize(argc, argv);
        return app.run(std::cout);
    } catch (const std::exception& e) {
        std::cerr << "simp-export-map: error: " << e.what() << "\n";
        return 1;
    }
}
