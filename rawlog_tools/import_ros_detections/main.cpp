/// simp-import-ros-detections: the authors' ROS detection array (CSV, 8 corners per object) +
/// robot poses + camera rig -> rawlog. doc/detector-io.md.
#include <simp/io/ToolArgs.h>
#include <simp/io/Tum.h>
#include <simp/labels/DetectionRawlog.h>
#include <simp/labels/RosDetectionsCsv.h>
#include <simp/obs/ObjectClasses.h>

#include <exception>
#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) {
    try {
        const auto args = simp::io::parseToolArgs(argc, argv, {"csv", "poses", "rig", "out"}, {});
        if (args.help) {
            std::cout << "Usage: simp-import-ros-detections --csv D.csv --poses poses.tum --rig rig.ini|rig.json --out Q.rawlog\n"
                         "Rows: timestamp, camera (name or rig index), then per object 8 corners x (x,y,z) in the\n"
                         "camera frame (Omni3D order), confidence, class id (the 14 classes of the paper).\n";
            return 0;
        }
        const auto rig = simp::labels::loadCameraRig(args.get("rig"));
        const auto set = simp::labels::readRosDetectionsCsv(args.get("csv"), simp::obs::defaultClassNames(), rig);
        const auto poses = simp::io::readTum(args.get("poses"));
        if (poses.empty()) throw std::runtime_error(args.get("poses") + ": no pose (a TUM file of t x y z qx qy qz qw lines)");
        const auto frames = simp::labels::framesFromDetections(set, poses, rig, args.get("csv"));
        simp::labels::writeDetectionRawlog(args.get("out"), frames);
        std::cout << "wrote " << args.get("out") << ": " << frames.size() << " frames, " << set.images.size()
                  << " images\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-import-ros-detections: error: " << e.what() << "\n";
        return 1;
    }
}
