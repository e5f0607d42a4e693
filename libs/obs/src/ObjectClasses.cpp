#include <simp/obs/ObjectClasses.h>

#include <algorithm>

namespace simp::obs {

const std::vector<std::string>& defaultClassNames() {
    static const std::vector<std::string> names = {
        "sink",  "door",  "oven",  "board", "table", "box",               "potted plant",
        "drawers", "sofa", "cabinet", "chair", "fire extinguisher", "person", "desk"};
    return names;
}

const std::vector<std::string>& tableIClassNames() {
    static const std::vector<std::string> names = {"board", "cabinet", "desk",  "drawers", "fire extinguisher",
                                                   "oven",  "potted plant", "sink", "sofa",   "table"};
    return names;
}

int classIndexOf(const std::vector<std::string>& names, const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

}  // namespace simp::obs
