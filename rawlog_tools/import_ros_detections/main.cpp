/// simp-import-ros-detections: the authors' ROS detection array (CSV, 8 corners per object) +
/// robot poses + camera rig -> rawlog. doc/detector-io.md.
#include <simp/io/CommandLine.h>
#include <simp/io/Tum.h>
#include <simp/detector_io/DetectionRawlog.h>
#include <simp/detector_io/RosDetectionsCsv.h>
#include <simp/obs/ObjectClasses.h>

#include <exception>
#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) {
    try {
        simp::io::CommandLine args("simp-import-ros-detections",
                                   "The authors' ROS detection array (CSV) + robot poses + camera rig -> rawlog (doc/detector-io.md).");
        args.required("csv", "D.csv", "rows: timestamp, camera (name or rig index), then per object 8 corners x (x,y,z)\n"
                                      "in the camera frame (Omni3D order), confidence, class id (the 14 classes of the paper)")
            .required("poses", "poses.tum", "robot poses (TUM), interpolated at each row's timestamp")
            .required("rig", "rig.ini|rig.json", "the camera rig")
            .required("out", "Q.rawlog", "the rawlog to write");
        if (!args.parse(argc, argv, std::cout)) return 0;
        const auto rig = simp::detector_io::loadCameraRig(args.value("rig"));
        const auto set = simp::detector_io::readRosDetectionsCsv(args.value("csv"), simp::obs::defaultClassNames(), rig);
        const auto poses = simp::io::readTum(args.value("poses"));
        if (poses.empty()) throw std::runtime_error(args.value("poses") + ": no pose (a TUM file of t x y z qx qy qz qw lines)");
        const auto frames = simp::detector_io::framesFromDetections(set, poses, rig, args.value("csv"));
        simp::detector_io::writeDetectionRawlog(args.value("out"), frames);
        std::cout << "wrote " << args.value("out") << ": " << frames.size() << " frames, " << set.images.size()
                  << " images\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-import-ros-detections: error: " << e.what() << "\n";
        return 1;
    }
}
