#include <simp/obs/ObjectStyle.h>
#include <simp/world/ObjectMap3D.h>

namespace simp::world {

void appendObjectBoxes(const ObjectMapData& map, mrpt::opengl::CSetOfObjects& out) {
    for (const auto& obj : map.objects) {
        const bool named = obj.class_id >= 0 && static_cast<std::size_t>(obj.class_id) < map.class_names.size();
        const std::string name = named ? map.class_names[static_cast<std::size_t>(obj.class_id)] : "?";
        obs::appendLabelledBox(obj.box, obs::classColorRgb(obj.class_id, map.class_names), name + " #" + std::to_string(obj.id), out);
    }
}

}  // namespace simp::world
