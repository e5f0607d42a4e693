/// simp-import-omni3d: Cube R-CNN / Omni3D predictions + robot poses + camera rig -> rawlog
/// (actions + sensory frames). doc/detector-io.md.
#include <simp/io/ToolArgs.h>
#include <simp/io/Tum.h>
#include <simp/labels/DetectionRawlog.h>
#include <simp/labels/Omni3DPredictions.h>

#include <exception>
#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) {
    try {
        const auto args = simp::io::parseToolArgs(argc, argv, {"predictions", "poses", "rig", "out"}, {});
        if (args.help) {
            std::cout << "Usage: simp-import-omni3d --predictions P.json --poses poses.tum --rig rig.ini|rig.json --out Q.rawlog\n"
                         "Writes one CActionCollection (odometry increment between the interpolated poses) +\n"
                         "CSensoryFrame (one CObservationObjects3D per camera) per image timestamp.\n";
            return 0;
        }
        const auto set = simp::labels::readOmni3DPredictions(args.get("predictions"));
        const auto poses = simp::io::readTum(args.get("poses"));
        if (poses.empty()) throw std::runtime_error(args.get("poses") + ": no pose (a TUM file of t x y z qx qy qz qw lines)");
        const auto rig = simp::labels::loadCameraRig(args.get("rig"));
        const auto frames = simp::labels::framesFromDetections(set, poses, rig, args.get("predictions"));
        simp::labels::writeDetectionRawlog(args.get("out"), frames);
        std::size_t n = 0;
        for (const auto& im : set.images) n += im.detections.size();
        std::cout << "wrote " << args.get("out") << ": " << frames.size() << " frames, " << set.images.size()
                  << " images, " << n << " detections\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-import-omni3d: error: " << e.what() << "\n";
        return 1;
    }
}
