// simp-example-rawlog: writes a small deterministic rawlog of 3D-object observations,
// e.g. to try `rawlog-edit --plugins build/lib/libsimp_obs.so --info -i example.rawlog`.
#include <simp/obs/ExampleRawlog.h>

#include <cstdlib>
#include <iostream>
#include <string>

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
            else if (a == "--frames") p.frames = std::stoul(next());
            else if (a == "--cameras") p.cameras = std::stoul(next());
            else if (a == "--detections") p.detections = std::stoul(next());
            else if (a == "--seed") p.seed = std::stoull(next());
            else throw std::invalid_argument("unknown option '" + a + "' (see --help)");
        }
        if (out.empty()) throw std::invalid_argument("missing --out FILE.rawlog (see --help)");
        const auto n = simp::obs::writeExampleRawlog(out, p);
        std::cout << "Wrote " << n << " observations in " << p.frames << " frames to " << out << "\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "simp-example-rawlog: error: " << e.what() << "\n";
        return 1;
    }
}
