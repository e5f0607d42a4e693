/// simp-import-map: the authors' map format -> a world directory.
/// The logic lives in simp::world::ImportMapApp (libs/world); usage: simp-import-map --help.
#include <simp/world/MapConvertApps.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::world::ImportMapApp app;
        app.initialize(argc, argv);
        return app.run(std::cout);
    } catch (const std::exception& e) {
        std::cerr << "simp-import-map: error: " << e.what() << "\n";
        return 1;
    }
}
