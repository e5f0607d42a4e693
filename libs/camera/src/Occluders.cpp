#include <simp/camera/Occluders.h>

namespace simp::camera {

bool occludes(const std::string& class_name) { return class_name != kDoorClass; }

std::vector<char> occludingClasses(const std::vector<std::string>& class_names) {
    std::vector<char> out;
    out.reserve(class_names.size());
    for (const std::string& name : class_names) out.push_back(occludes(name) ? 1 : 0);
    return out;
}

}  // namespace simp::camera
