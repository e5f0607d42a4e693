#include <simp/maps/WorldMultiMap.h>

namespace simp::maps {

mrpt::maps::CMultiMetricMap::Ptr makeMultiMetricMap(const world::World& world,
                                                    const CObjectMap::TLikelihoodOptions& likelihood) {
    auto multi = mrpt::maps::CMultiMetricMap::Create();
    auto grid = mrpt::maps::COccupancyGridMap2D::Create();
    *grid = world.floorplan;
    auto objects = CObjectMap::Create();
    objects->likelihoodOptions = likelihood;
    objects->setData(world.objects);
    multi->maps.push_back(grid);
    multi->maps.push_back(objects);
    return multi;
}

mrpt::maps::CMultiMetricMap::Ptr loadMultiMetricMap(const std::string& world_dir,
                                                    const CObjectMap::TLikelihoodOptions& likelihood) {
    return makeMultiMetricMap(world::loadWorld(world_dir), likelihood);
}

}  // namespace simp::maps
