/// \file World.cpp
/// A world directory (doc/formats.md): floorplan.yaml + image, rooms.png (optional), objects.json.

#include <simp/world/World.h>

#include <filesystem>
#include <stdexcept>

namespace simp::world {

namespace fs = std::filesystem;

World loadWorld(const std::string& dir) {
    if (!fs::is_directory(dir)) throw std::runtime_error("world directory '" + dir + "' does not exist");
    const std::string yaml = (fs::path(dir) / "floorplan.yaml").string();
    const std::string objects = (fs::path(dir) / "objects.json").string();
    const std::string rooms = (fs::path(dir) / "rooms.png").string();
    if (!fs::exists(yaml)) throw std::runtime_error(yaml + ": missing (a world directory needs floorplan.yaml)");
    if (!fs::exists(objects)) throw std::runtime_error(objects + ": missing (a world directory needs objects.json)");
    World w;
    loadRosMap(yaml, w.floorplan);
    if (fs::exists(rooms)) {
        const RosMapYaml meta = readRosMapYaml(yaml);
        w.rooms = loadRoomMap(rooms, meta.resolution_m, meta.origin_x_m, meta.origin_y_m);
        if (static_cast<unsigned>(w.rooms.ids.cols) != w.floorplan.getSizeX() ||
            static_cast<unsigned>(w.rooms.ids.rows) != w.floorplan.getSizeY())
            throw std::runtime_error(rooms + ": size " + std::to_string(w.rooms.ids.cols) + "x" +
                                     std::to_string(w.rooms.ids.rows) + " differs from the floor plan's " +
                                     std::to_string(w.floorplan.getSizeX()) + "x" +
                                     std::to_string(w.floorplan.getSizeY()));
    }
    w.objects = loadObjectMap(objects);
    return w;
}

void saveWorld(const World& world, const std::string& dir) {
    fs::create_directories(dir);
    saveRosMap(world.floorplan, (fs::path(dir) / "floorplan.yaml").string());
    const std::string rooms = (fs::path(dir) / "rooms.png").string();
    if (!world.rooms.empty()) {
        if (static_cast<unsigned>(world.rooms.ids.cols) != world.floorplan.getSizeX() ||
            static_cast<unsigned>(world.rooms.ids.rows) != world.floorplan.getSizeY())
            throw std::runtime_error(rooms + ": room raster size differs from the floor plan");
        saveRoomMap(world.rooms, rooms);
    } else if (fs::exists(rooms)) {
        fs::remove(rooms);  // a stale raster would not belong to this world
    }
    saveObjectMap(world.objects, (fs::path(dir) / "objects.json").string());
}

}  // namespace simp::world
