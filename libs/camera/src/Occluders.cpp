#include <simp/camera/Occluders.h>

namespace simp::camera {

OcclusionKind occlusionOf(const std::string& class_name) {
    if (class_name == kDoorClass) return kSeeThrough;
    if (class_name == kTableClass) return kOpenBelow;
    return kSolid;
}

bool occludes(const std::string& class_name) { return occlusionOf(class_name) != kSeeThrough; }

std::vector<char> occludingClasses(const std::vector<std::string>& class_names) {
    std::vector<char> out;
    out.reserve(class_names.size());
    for (const std::string& name : class_names) out.push_back(occlusionOf(name));
    return out;
}

}  // namespace simp::camera
