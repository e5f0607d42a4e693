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

char occlusionOfClassId(const std::vector<char>& class_kinds, int class_id) {
    return class_id < 0 || static_cast<std::size_t>(class_id) >= class_kinds.size() ? static_cast<char>(kSolid)
                                                                                     : class_kinds[static_cast<std::size_t>(class_id)];
}

}  // namespace simp::camera
