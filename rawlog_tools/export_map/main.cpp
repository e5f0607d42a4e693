/// simp-export-map: a world directory -> the authors' map format (for their ROS tools), MRPT's
/// .gridmap (for pf-localization) and an OctoMap (for 3D planners).
/// The logic lives in simp::world::ExportMapApp (libs/world) and libs/export3d; usage: simp-export-map --help.
#include <simp/export3d/OctomapExport.h>
#include <simp/world/MapConvertApps.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::world::ExportMapApp app;
        app.octomap_writer = simp::export3d::exportOctomapCommand;
        app.initialize(argc, argv);
        return app.run(std::cout);
    } catch (const std::exception& e) {
        std::cerr << "simp-export-map: error: " << e.what() << "\n";
        return 1;
    }
}
