// simp-example-rawlog: writes a small deterministic rawlog of 3D-object observations,
// e.g. to try `rawlog-edit --plugins build/lib/libsimp_obs.so --info -i example.rawlog`.
#include <simp/obs/ExampleRawlog.h>

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

/// A non-negative decimal integer, all of the text (std::stoul accepted "-1" as 2^64 - 1 and "3x").
std::uint64_t parseCount(const std::string& option, const std::string& text) {
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
        throw std::invalid_argument("option " + option + ": '" + text + "' is not a non-negative integer");
    return v;
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
            else if (a == "--frames") p.frames = parseCount(a, next());
            else if (a == "--cameras") p.cameras = parseCount(a, next());
            else if (a == "--detections") p.detections = parseCount(a, next());
            else if (a == "--seed") p.seed = parseCount(a, next());
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
