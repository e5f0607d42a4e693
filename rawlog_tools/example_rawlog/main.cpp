// simp-example-rawlog: writes a small deterministic rawlog of 3D-object observations,
// e.g. to try `rawlog-edit --plugins build/lib/libsimp_obs.so --info -i example.rawlog`.
#include <simp/io/StrictNumber.h>
#include <simp/obs/ExampleRawlog.h>
#include <simp/obs/InputLimits.h>

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>

namespace {

/// A count within the documented range (ExampleRawlog.h), strictly parsed: "-1", "3x", "1e3" are errors.
std::size_t parseCount(const std::string& option, const std::string& text, std::size_t lo, std::size_t hi) {
    return static_cast<std::size_t>(
        simp::io::parseInteger(text, "option " + option, static_cast<std::int64_t>(lo), static_cast<std::int64_t>(hi)));
}

}  // namespace

int main(int argc, char** argv) {
    try {
        simp::obs::ExampleRawlogParams p;
        std::string out;
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            auto next = [&]() -> std::string {
                if (i + 1 >= argc) throw std::invalid_argument("option " + a + " needs a value");
                return argv[++i];
            };
            if (a == "--help" || a == "-h") {
                std::cout << "Usage: simp-example-rawlog --out FILE.rawlog [--frames N] [--cameras N] "
                             "[--detections N] [--seed S]\n"
                             "Writes a deterministic rawlog of simp::obs::CObservationObjects3D (one per camera\n"
                             "per frame) for trying MRPT's tools with the plugin.\n";
                return 0;
            } else if (a == "--out") out = next();
            else if (a == "--frames") p.frames = parseCount(a, next(), 1, simp::obs::kMaxExampleFrames);
            else if (a == "--cameras") p.cameras = parseCount(a, next(), 1, simp::obs::kMaxExampleCameras);
            else if (a == "--detections") p.detections = parseCount(a, next(), 0, simp::obs::limits::kMaxDetectionsPerFrame);
            else if (a == "--seed")
                p.seed = static_cast<std::uint64_t>(
                    simp::io::parseInteger(next(), "option --seed", 0, std::numeric_limits<std::int64_t>::max()));
            else throw std::invalid_argument("unknown option '" + a + "' (see --help)");
        }
        if (out.empty()) throw std::invalid_argument("missing --out FILE.rawlog (see --help)");
        simp::obs::validateExampleRawlogParams(p);  // before creating the file
        const auto n = simp::obs::writeExampleRawlog(out, p);
        std::cout << "Wrote " << n << " observations in " << p.frames << " frames to " << out << "\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-example-rawlog: error: " << e.what() << "\n";
        return 1;
    }
}
