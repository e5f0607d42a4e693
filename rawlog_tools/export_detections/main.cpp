/// simp-export-detections: a rawlog's 3D detections -> CSV (the ROS detection-array layout) and
/// Omni3D predictions JSON, its odometry path -> TUM. doc/detector-io.md.
#include <simp/io/ToolArgs.h>
#include <simp/io/Tum.h>
#include <simp/labels/DetectionRawlog.h>
#include <simp/labels/Omni3DPredictions.h>
#include <simp/labels/RosDetectionsCsv.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    try {
        const auto args =
            simp::io::parseToolArgs(argc, argv, {"rawlog"}, {"out-csv", "out-json", "out-tum"});
        if (args.help) {
            std::cout << "Usage: simp-export-detections --rawlog Q.rawlog [--out-csv D.csv] [--out-json D.json] [--out-tum odom.tum]\n"
                         "At least one output. CSV = simp-import-ros-detections input, JSON = simp-import-omni3d input,\n"
                         "TUM = odometry increments composed from the identity at the first frame.\n";
            return 0;
        }
        if (!args.has("out-csv") && !args.has("out-json") && !args.has("out-tum"))
            throw std::invalid_argument("nothing to do: give --out-csv, --out-json and/or --out-tum");
        const auto frames = simp::obs::readRawlog(args.get("rawlog"));
        const auto set = simp::labels::detectionsFromFrames(frames);
        if (args.has("out-csv")) simp::labels::writeRosDetectionsCsv(args.get("out-csv"), set);
        if (args.has("out-json")) simp::labels::writeOmni3DPredictions(args.get("out-json"), set);
        if (args.has("out-tum")) simp::io::writeTum(args.get("out-tum"), simp::labels::integrateOdometry(frames));
        std::cout << "exported " << frames.size() << " frames, " << set.images.size() << " images\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-export-detections: error: " << e.what() << "\n";
        return 1;
    }
}
