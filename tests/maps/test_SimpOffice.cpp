// The sensor model on the authors' ground-truth map (skipped when the data is absent).
#include <gtest/gtest.h>
#include <simp/maps/CObjectMap.h>
#include <simp/world/SimpFormat.h>

#include "TestMaps.h"

#include <filesystem>
#include <random>

namespace simp::maps {
namespace {

using mrpt::math::TPose2D;

TEST(SimpOffice, TruePoseBeatsEveryPoseFartherThanOneMetre) {
    const std::string dir = std::string(SIMP_SHARED_DATA_DIR) + "/simp-office";
    if (!std::filesystem::exists(dir + "/global_variance.json"))
        GTEST_SKIP() << "authors' data not found at " << dir << " (optional, read-only)";
    const auto data = world::importSimpMap(dir).objects;
    CObjectMap map;
    ASSERT_NO_THROW(map.setData(data)) << "every simp-office object has a noise model";

    // Detections equal to the 4 objects nearest to a pose near the middle of the map.
    const auto& mid = data.objects[data.objects.size() / 2].box.center;
    const TPose2D truth(mid.x() - 1.5, mid.y(), 0.0);
    std::vector<std::size_t> order(data.objects.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return std::hypot(data.objects[a].box.center.x() - truth.x, data.objects[a].box.center.y() - truth.y) <
               std::hypot(data.objects[b].box.center.x() - truth.x, data.objects[b].box.center.y() - truth.y);
    });
    const auto o = test::detect(data, truth, {order[0], order[1], order[2], order[3]}, 0.95f);
    const double at_truth = map.computeObservationLikelihood(o, test::pose3D(truth));

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ux(-14, 13), uy(-11, 3), uphi(-M_PI, M_PI);
    int far = 0;
    for (int i = 0; i < 5000; ++i) {
        const TPose2D p(ux(rng), uy(rng), uphi(rng));
        if (std::hypot(p.x - truth.x, p.y - truth.y) < 1.0) continue;
        ++far;
        ASSERT_LT(map.computeObservationLikelihood(o, test::pose3D(p)), at_truth) << p.asString();
    }
    EXPECT_GT(far, 4500);
}

}  // namespace
}  // namespace simp::maps
