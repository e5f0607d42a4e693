// simp-example-rawlog: writes a small deterministic rawlog of 3D-object observations,
// e.g. to try `rawlog-edit --plugins build/lib/libsimp_obs.so --info -i example.rawlog`.
#include <simp/io/CommandLine.h>
#include <simp/obs/ExampleRawlog.h>
#include <simp/obs/InputLimits.h>

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>

int main(int argc, char** argv) {
    try {
        simp::obs::ExampleRawlogParams p;
        simp::io::CommandLine args("simp-example-rawlog",
                                   "Writes a deterministic rawlog of simp::obs::CObservationObjects3D (one per camera\n"
                                   "per frame) for trying MRPT's tools with the plugin.");
        args.required("out", "FILE.rawlog", "the rawlog to write")
            .option("frames", "N", "frames, in [1, " + std::to_string(simp::obs::kMaxExampleFrames) + "]")
            .option("cameras", "N", "cameras, in [1, " + std::to_string(simp::obs::kMaxExampleCameras) + "]")
            .option("detections", "N", "detections per frame, in [0, " + std::to_string(simp::obs::limits::kMaxDetectionsPerFrame) + "]")
            .option("seed", "S", "random seed");
        if (!args.parse(argc, argv, std::cout)) return 0;
        const std::string out = args.value("out");
        using Count = std::int64_t;
        if (auto n = args.integer("frames", 1, static_cast<Count>(simp::obs::kMaxExampleFrames))) p.frames = static_cast<std::size_t>(*n);
        if (auto n = args.integer("cameras", 1, static_cast<Count>(simp::obs::kMaxExampleCameras))) p.cameras = static_cast<std::size_t>(*n);
        if (auto n = args.integer("detections", 0, static_cast<Count>(simp::obs::limits::kMaxDetectionsPerFrame)))
            p.detections = static_cast<std::size_t>(*n);
        if (auto s = args.integer("seed", 0, std::numeric_limits<Count>::max())) p.seed = static_cast<std::uint64_t>(*s);
        simp::obs::validateExampleRawlogParams(p);  // before creating the file
        const auto n = simp::obs::writeExampleRawlog(out, p);
        std::cout << "Wrote " << n << " observations in " << p.frames << " frames to " << out << "\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-example-rawlog: error: " << e.what() << "\n";
        return 1;
    }
}
