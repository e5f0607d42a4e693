// Writes the seed corpus of the fuzz targets from the project's own generated files:
// make_seeds OUT_DIR creates OUT_DIR/<target>/ with a few valid inputs each (< 10 KB mostly).
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/io/Tum.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/ExampleRawlog.h>
#include <simp/world/ObjectMapData.h>
#include <simp/world/World.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

namespace fs = std::filesystem;

namespace {

std::string readAll(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

void writeAll(const fs::path& path, const std::string& bytes) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
}

simp::world::ObjectMapData smallMap() {
    simp::world::ObjectMapData d;
    d.class_names = {"table", "chair"};
    d.class_noise.assign(2, std::nullopt);
    simp::model::NoiseModel n;
    n.mean_m = {0.05, -0.02};
    n.cov_m2 << 0.1, 0.0, 0.0, 0.2;
    n.exponent_b = 2.0;
    d.class_noise[0] = n;
    d.class_noise[1] = n;  // every class modelled: the simp sensor model refuses a class without one
    for (int i = 0; i < 3; ++i) {
        simp::world::MapObject o;
        o.id = i + 1;
        o.class_id = i % 2;
        o.box.center = {1.0 + i, 2.0, 0.4};
        o.box.size = {1.2, 0.6, 0.8};
        if (i == 2) o.noise = n;
        d.objects.push_back(o);
    }
    return d;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: make_seeds OUT_DIR SOURCE_DIR\n";
        return 2;
    }
    const fs::path out = argv[1];
    const fs::path src = argv[2];
    const fs::path tmp = out / "tmp";
    fs::create_directories(tmp);
    try {
        // rawlog: 2 frames x 2 cameras x 2 detections, and a 1-frame variant.
        for (std::size_t frames : {1u, 2u}) {
            simp::obs::ExampleRawlogParams p;
            p.frames = frames;
            p.cameras = 2;
            p.detections = 2;
            const auto path = (tmp / "x.rawlog").string();
            simp::obs::writeExampleRawlog(path, p);
            writeAll(out / "rawlog" / ("example_" + std::to_string(frames) + ".rawlog"), readAll(path));
        }
        // object map, binary (CObjectMap archive) and JSON.
        simp::maps::CObjectMap map;
        map.setData(smallMap());
        {
            mrpt::io::CFileOutputStream f((tmp / "map.bin").string());
            auto a = mrpt::serialization::archiveFrom(f);
            a << map;
        }
        writeAll(out / "object_map_bin" / "small.bin", readAll((tmp / "map.bin").string()));
        simp::world::saveObjectMap(smallMap(), (tmp / "objects.json").string());
        writeAll(out / "world_json" / "small.json", readAll((tmp / "objects.json").string()));
        // floor plan: yaml (byte 0 even) and image (byte 0 odd) variants.
        mrpt::maps::COccupancyGridMap2D grid;
        simp::world::setGridExactly(grid, -1.0, -1.0, 8, 6, 0.05, 1.0f);
        simp::world::saveRosMap(grid, (tmp / "fp.yaml").string());
        writeAll(out / "floorplan" / "yaml", std::string(1, '\0') + readAll((tmp / "fp.yaml").string()));
        writeAll(out / "floorplan" / "png", std::string(1, '\1') + readAll((tmp / "fp.png").string()));
        writeAll(out / "floorplan" / "pgm", std::string(1, '\1') + "P2\n3 2\n255\n0 205 254\n254 0 205\n");
        // .ini and lists
        writeAll(out / "ini_lists" / "sim.ini", "[sequence]\nduration_s = 60\n[m]\nconfidence_thresholds=chair:0.3, door:0.5\n");
        writeAll(out / "ini_lists" / "list", "chair:0.7, potted plant:0.9, \"sofa\":1e-3");
        // TUM
        simp::io::writeTum((tmp / "poses.tum").string(), {{0.0, {0, 0, 0}}, {0.1, {0.05, 0, 0.01}}, {0.2, {0.1, 0.01, 0.02}}});
        writeAll(out / "tum" / "poses.tum", readAll((tmp / "poses.tum").string()));
        // detector imports: the project's test files (JSON: byte 0 even, CSV: odd)
        const fs::path det = src / "tests" / "data" / "detector_io";
        writeAll(out / "detections" / "predictions", std::string(1, '\0') + readAll((det / "predictions.json").string()));
        writeAll(out / "detections" / "csv", std::string(1, '\1') + readAll((det / "detections.csv").string()));
    } catch (const std::exception& e) {
        std::cerr << "make_seeds: " << e.what() << "\n";
        return 1;
    }
    fs::remove_all(tmp);
    return 0;
}
