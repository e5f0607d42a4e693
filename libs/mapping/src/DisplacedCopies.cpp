/// \file DisplacedCopies.cpp
/// New objects that may be an earlier object displaced (DisplacedCopies.h).
#include <simp/mapping/DisplacedCopies.h>

namespace simp::mapping {

std::vector<std::vector<int>> displacedCopyCandidates(const world::ObjectMapData& map, std::int64_t first_new_id,
                                                      double max_distance_m) {
    const auto& objs = map.objects;
    std::vector<std::vector<int>> out(objs.size());
    std::vector<int> fresh;
    for (std::size_t k = 0; k < objs.size(); ++k)
        if (objs[k].id >= first_new_id) fresh.push_back(static_cast<int>(k));
    if (fresh.empty() || max_distance_m <= 0) return out;
    for (std::size_t k = 0; k < objs.size(); ++k) {
        const world::MapObject& o = objs[k];
        if (o.id >= first_new_id) continue;
        for (const int f : fresh) {  // ascending: the list is sorted
            const world::MapObject& n = objs[static_cast<std::size_t>(f)];
            if (n.class_id == o.class_id && (n.box.center - o.box.center).head<2>().norm() <= max_distance_m)
                out[k].push_back(f);
        }
    }
    return out;
}

}  // namespace simp::mapping
