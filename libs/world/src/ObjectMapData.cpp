#include <simp/obs/ObjectClasses.h>
#include <simp/world/ObjectMapData.h>

#include <map>
#include <stdexcept>

namespace simp::world {

int ObjectMapData::classId(const std::string& name) const {
    return obs::classIndexOf(class_names, name);
}

std::optional<model::NoiseModel> ObjectMapData::noiseOf(const MapObject& o) const {
    if (o.noise) return o.noise;
    if (o.class_id >= 0 && static_cast<std::size_t>(o.class_id) < class_noise.size())
        return class_noise[static_cast<std::size_t>(o.class_id)];
    return std::nullopt;
}

double defaultClassHeight(const std::string& class_name) {
    // Typical vertical extents (m) of office furniture; a board is a wall whiteboard's
    // vertical extent, a door its leaf. doc/formats.md lists the same table.
    static const std::map<std::string, double> heights = {
        {"sink", 0.9},    {"door", 2.0},          {"oven", 0.9},    {"board", 1.2},
        {"table", 0.75},  {"box", 0.4},           {"potted plant", 1.0},
        {"drawers", 0.7}, {"sofa", 0.85},         {"cabinet", 1.8}, {"chair", 0.9},
        {"fire extinguisher", 0.6},               {"person", 1.7},  {"desk", 0.75}};
    const auto it = heights.find(class_name);
    if (it == heights.end())
        throw std::invalid_argument("defaultClassHeight: no default height for class '" + class_name +
                                    "' (known: the 14 classes of simp::obs::defaultClassNames())");
    return it->second;
}

}  // namespace simp::world
