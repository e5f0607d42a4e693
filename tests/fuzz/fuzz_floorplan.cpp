// libFuzzer target: the floor plan (ROS map_server YAML + image, simp::world::loadRosMap).
// The first byte picks what is fuzzed: even = the YAML text (with a valid 4 x 3 px PGM image),
// odd = the image bytes (with a valid YAML naming it).
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <simp/world/World.h>

#include "FuzzUtil.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const std::string dir = simp_fuzz::scratchDir();
    const std::string yaml = dir + "/map.yaml";
    if (data[0] % 2 == 0) {
        static const std::string pgm = "P2\n4 3\n255\n0 0 0 0\n0 254 254 0\n0 0 0 0\n";
        simp_fuzz::writeInput("map.pgm", reinterpret_cast<const std::uint8_t*>(pgm.data()), pgm.size());
        simp_fuzz::writeInput("map.yaml", data + 1, size - 1);
    } else {
        static const std::string y =
            "image: map.img\nresolution: 0.05\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
        simp_fuzz::writeInput("map.yaml", reinterpret_cast<const std::uint8_t*>(y.data()), y.size());
        simp_fuzz::writeInput("map.img", data + 1, size - 1);
    }
    simp_fuzz::expectNoCrash([&] {
        mrpt::maps::COccupancyGridMap2D grid;
        simp::world::loadRosMap(yaml, grid);
    });
    return 0;
}
