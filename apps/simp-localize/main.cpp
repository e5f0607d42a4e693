/// simp-localize: global localization with 3D object detections on a floor plan.
/// All logic is in simp::localization::LocalizeApp (doc/localization.md).

#include <simp/localization/LocalizeApp.h>

#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::localization::LocalizeApp app;
        app.initialize(argc, argv);
        app.run();
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-localize: error: " << simp::localization::describeError(e) << std::endl;
        return 1;
    }
}
