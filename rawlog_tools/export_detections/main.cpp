/// simp-export-detections: a rawlog's 3D detections -> CSV (the ROS detection-array layout) and
/// Omni3D predictions JSON, its odometry path -> TUM. doc/detector-io.md.
#include <simp/io/CommandLine.h>
#include <simp/io/Tum.h>
#include <simp/detector_io/DetectionRawlog.h>
#include <simp/detector_io/Omni3DPredictions.h>
#include <simp/detector_io/RosDetectionsCsv.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        simp::io::CommandLine args("simp-export-detections",
                                   "A rawlog's 3D detections -> CSV (the ROS detection-array layout) and Omni3D predictions\n"
                                   "JSON, its odometry path -> TUM (doc/detector-io.md).");
        args.required("rawlog", "Q.rawlog", "the rawlog to read")
            .option("out-csv", "D.csv", "detections as CSV (simp-import-ros-detections input)")
            .option("out-json", "D.json", "detections as Omni3D predictions JSON (simp-import-omni3d input)")
            .option("out-tum", "odom.tum", "odometry increments composed from the identity at the first frame")
            .notes("At least one output.");
        if (!args.parse(argc, argv, std::cout)) return 0;
        if (!args.has("out-csv") && !args.has("out-json") && !args.has("out-tum"))
            throw std::invalid_argument("nothing to do: give --out-csv, --out-json and/or --out-tum");
        const auto frames = simp::obs::readRawlog(args.value("rawlog"));
        const auto set = simp::detector_io::detectionsFromFrames(frames);
        if (args.has("out-csv")) simp::detector_io::writeRosDetectionsCsv(args.value("out-csv"), set);
        if (args.has("out-json")) simp::detector_io::writeOmni3DPredictions(args.value("out-json"), set);
        if (args.has("out-tum")) simp::io::writeTum(args.value("out-tum"), simp::detector_io::integrateOdometry(frames));
        std::cout << "exported " << frames.size() << " frames, " << set.images.size() << " images\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-export-detections: error: " << e.what() << "\n";
        return 1;
    }
}
