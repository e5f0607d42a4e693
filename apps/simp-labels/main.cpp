/// simp-labels: Omni3D training labels from a ground-truth world, posed images and 2D detections
/// (paper Sec. "Label Generation for 3D Object Detection"). Logic: simp::labels::LabelsApp.
#include <simp/labels/LabelsApp.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::labels::LabelsApp app;
        if (!app.initialize(argc, argv, std::cout)) return 0;
        return app.run(std::cout);
    } catch (const std::exception& e) {
        std::cerr << "simp-labels: error: " << e.what() << "\n";
        return 1;
    }
}
