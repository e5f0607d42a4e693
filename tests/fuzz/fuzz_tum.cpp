// libFuzzer target: the TUM trajectory reader (simp::io::readTum) and pose interpolation.
#include <simp/io/Tum.h>

#include "FuzzUtil.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = simp_fuzz::writeInput("poses.tum", data, size);
    simp_fuzz::expectNoCrash([&] {
        const auto poses = simp::io::readTum(path);
        mrpt::math::TPose2D p;
        if (!poses.empty()) simp::io::interpolatePose(poses, 0.5 * (poses.front().t_s + poses.back().t_s), p);
    });
    return 0;
}
