/// simp-import-omni3d: Cube R-CNN / Omni3D predictions + robot poses + camera rig -> rawlog
/// (actions + sensory frames). doc/detector-io.md.
#include <simp/io/CommandLine.h>
#include <simp/io/Tum.h>
#include <simp/detector_io/DetectionRawlog.h>
#include <simp/detector_io/Omni3DPredictions.h>

#include <exception>
#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) {
    try {
        simp::io::CommandLine args("simp-import-omni3d",
                                   "Writes one CActionCollection (odometry increment between the interpolated poses) +\n"
                                   "CSensoryFrame (one CObservationObjects3D per camera) per image timestamp (doc/detector-io.md).");
        args.required("predictions", "P.json", "Cube R-CNN / Omni3D predictions")
            .required("poses", "poses.tum", "robot poses (TUM), interpolated at each image timestamp")
            .required("rig", "rig.ini|rig.json", "the camera rig")
            .required("out", "Q.rawlog", "the rawlog to write");
        if (!args.parse(argc, argv, std::cout)) return 0;
        const auto set = simp::detector_io::readOmni3DPredictions(args.value("predictions"));
        const auto poses = simp::io::readTum(args.value("poses"));
        if (poses.empty()) throw std::runtime_error(args.value("poses") + ": no pose (a TUM file of t x y z qx qy qz qw lines)");
        const auto rig = simp::detector_io::loadCameraRig(args.value("rig"));
        const auto frames = simp::detector_io::framesFromDetections(set, poses, rig, args.value("predictions"));
        simp::detector_io::writeDetectionRawlog(args.value("out"), frames);
        std::size_t n = 0;
        for (const auto& im : set.images) n += im.detections.size();
        std::cout << "wrote " << args.value("out") << ": " << frames.size() << " frames, " << set.images.size()
                  << " images, " << n << " detections\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-import-omni3d: error: " << e.what() << "\n";
        return 1;
    }
}
