#include <simp/eval/Plots.h>
#include <simp/eval/PngFile.h>
#include <simp/sim/Sequence.h>

namespace simp::sim {

void writeOverviewPng(const world::World& world, const std::vector<io::StampedPose2D>& trajectory,
                      const std::string& png_path, std::size_t jump_step) {
    eval::MapLayers layers;
    layers.floorplan = &world.floorplan;
    layers.objects = &world.objects;
    layers.ground_truth = trajectory;
    layers.ground_truth_jump = jump_step;
    eval::writePng(png_path, eval::drawTrajectoryMap(layers));
}

}  // namespace simp::sim
