// m_p (Eqs. shiftdist, globaldist): the raster lookup against brute force over all objects.
#include <gtest/gtest.h>
#include <simp/maps/ObjectProbabilityMap.h>
#include <simp/model/NoiseModel.h>

#include "TestMaps.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace simp::maps {
namespace {

/// A cluttered map: 60 objects of two classes, random poses, noise with b in {2, 4}, some
/// objects with their own noise (overriding the class's), close enough to compete.
world::ObjectMapData randomMap(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ux(0.0, 8.0), uy(0.0, 6.0), uyaw(-M_PI, M_PI), usig(0.15, 0.4),
        umean(-0.1, 0.1), usize(0.3, 1.5);
    world::ObjectMapData m;
    m.class_names = {"chair", "table"};
    m.class_noise = {test::noise(0.2, 0.1, 2.0, 0.05, 0.0), test::noise(0.3, 0.2, 4.0)};
    for (int i = 0; i < 60; ++i) {
        world::MapObject o;
        o.id = i;
        o.class_id = i % 2;
        o.box = geometry::makeUprightBox({ux(rng), uy(rng), 0.5}, {usize(rng), usize(rng), 1.0}, uyaw(rng));
        if (i % 3 == 0) o.noise = test::noise(usig(rng), usig(rng), (i % 2) ? 2.0 : 4.0, umean(rng), umean(rng));
        m.objects.push_back(o);
    }
    return m;
}

TEST(ObjectProbabilityMap, LookupMatchesBruteForceWithinTheRasterBound) {
    const auto data = randomMap(7);
    ObjectProbabilityMap::Options opt;
    opt.resolution_m = 0.05;
    opt.min_probability = 1e-4;
    const ObjectProbabilityMap mp(data, opt);

    for (int cls = 0; cls < 2; ++cls) {
        // Bound (see doc/object-map.md): with h = res / sqrt(2) the distance from a point to its
        // cell centre and L = max_o slope_o / sigma_min_o the largest gradient of any p_o,
        //   max_o p_o(c) - p_{o_max}(c) <= 2 L h    (argmax taken at the cell centre),
        //   and a point of an empty cell has max_o p_o(c) < p_min + L h.
        double L = 0;
        for (const auto o : mp.objectsOf(cls)) {
            const auto& d = mp.distribution(static_cast<std::size_t>(o));
            L = std::max(L, model::maxSlopeMahalanobis(2.0 * d.half_b) / d.sigma_min_m);
        }
        const double h = opt.resolution_m / std::sqrt(2.0);
        const double bound_hit = 2.0 * L * h + 1e-6;  // + float storage of the cell maxima
        const double bound_empty = opt.min_probability + L * h;

        std::mt19937 rng(11 + cls);
        std::uniform_real_distribution<double> ux(-1.0, 9.0), uy(-1.0, 7.0);
        int same = 0, differ = 0, differ_supported = 0, nonzero = 0;
        double worst = 0;
        for (int i = 0; i < 20000; ++i) {
            const double x = ux(rng), y = uy(rng);
            const auto fast = mp.lookup(cls, x, y);
            const auto slow = mp.bruteForce(cls, x, y);
            if (slow.p > 1e-3) ++nonzero;
            if (fast.object == slow.object) {
                ++same;
                EXPECT_EQ(fast.p, slow.p);  // same object: the very same formula
                continue;
            }
            ++differ;
            if (slow.p >= opt.min_probability) ++differ_supported;
            const double err = slow.p - fast.p;
            worst = std::max(worst, err);
            ASSERT_GE(err, 0.0);
            if (fast.object < 0)
                ASSERT_LT(slow.p, bound_empty) << "at (" << x << ", " << y << ")";
            else
                ASSERT_LE(err, bound_hit) << "at (" << x << ", " << y << ")";
        }
        // Where some p_o >= p_min the raster agrees with brute force on the argmax almost
        // everywhere: disagreements are confined to cells crossed by an argmax boundary or by
        // the support edge (a band one cell wide).
        EXPECT_GT(nonzero, 2000) << "the test points must cover the objects";
        EXPECT_LT(differ_supported, nonzero / 20) << "more than 5% argmax disagreements";
        std::cout << "class " << cls << ": " << same << " equal, " << differ << " differ (" << differ_supported
                  << " with p >= p_min, of " << nonzero << " with p > 1e-3), worst p error " << worst << " (bound "
                  << bound_hit << ")\n";
    }
}

TEST(ObjectProbabilityMap, OutsideTheRasterIsZero) {
    const auto data = test::smallMap();
    const ObjectProbabilityMap mp(data, {});
    const int chair = data.classId("chair");
    const auto far = mp.lookup(chair, 1000.0, -1000.0);
    EXPECT_EQ(far.object, -1);
    EXPECT_EQ(far.p, 0.0);
    const auto nan = mp.lookup(chair, std::nan(""), 0.0);
    EXPECT_EQ(nan.object, -1);
    // Classes with no object: hasClass false.
    EXPECT_FALSE(mp.hasClass(data.classId("sofa")));
    EXPECT_TRUE(mp.hasClass(chair));
}

TEST(ObjectProbabilityMap, ClassWithoutNoiseIsAnErrorOrSkipped) {
    auto data = test::smallMap();
    data.class_noise[data.classId("door")].reset();
    try {
        ObjectProbabilityMap mp(data, {});
        FAIL() << "expected an exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'door'"), std::string::npos) << e.what();
    }
    ObjectProbabilityMap::Options opt;
    opt.skip_classes_without_noise = true;
    const ObjectProbabilityMap mp(data, opt);
    EXPECT_FALSE(mp.hasClass(data.classId("door")));
    ASSERT_EQ(mp.skippedClasses().size(), 1u);
    EXPECT_EQ(mp.skippedClasses()[0], data.classId("door"));
    // A per-object noise is enough for its class.
    data.objects[3].noise = test::noise(0.3, 0.1, 2.0);
    EXPECT_NO_THROW(ObjectProbabilityMap(data, {}));
}

TEST(ObjectProbabilityMap, UnmodelledClassGetsTheIsotropicDefault) {
    auto data = test::smallMap();
    const int door = data.classId("door");
    data.class_noise[static_cast<std::size_t>(door)].reset();
    ObjectProbabilityMap::Options opt;
    opt.unmodelled_noise_std_m = 0.3;  // no skip needed: nothing is unmodelled any more
    const ObjectProbabilityMap mp(data, opt);
    ASSERT_TRUE(mp.hasClass(door));
    EXPECT_TRUE(mp.skippedClasses().empty());
    for (const std::int32_t o : mp.objectsOf(door)) {
        const auto& d = mp.distribution(static_cast<std::size_t>(o));
        // Zero mean shift, 0.3 m in every direction: the density is the same 0.3 m off the centre
        // along x and along y, and half its peak at 0.3 * sqrt(2 ln 2) m (a Gaussian, b = 2).
        const Eigen::Vector2d c = d.mean_world_m;
        const double peak = d.probability(c.x(), c.y());
        EXPECT_NEAR(d.probability(c.x() + 0.3, c.y()), d.probability(c.x(), c.y() + 0.3), 1e-12);
        EXPECT_NEAR(d.probability(c.x() + 0.3 * std::sqrt(2.0 * std::log(2.0)), c.y()) / peak, 0.5, 1e-9);
        EXPECT_NEAR(d.sigma_x_m, 0.3, 1e-12);
        EXPECT_NEAR(d.sigma_y_m, 0.3, 1e-12);
    }
    opt.unmodelled_noise_std_m = -0.1;
    EXPECT_THROW(ObjectProbabilityMap(data, opt), std::invalid_argument);
}

TEST(ObjectProbabilityMap, CentreNoiseFloorUsesEachModelWithoutItsFootprint) {
    // centre_noise_floor = 0 keeps every object's model (the paper); > 0 builds each p_o from
    // model::withoutFootprint(its model, its box, its noise source, floor): narrower, same centre.
    const auto data = test::smallMap();
    const ObjectProbabilityMap as_is(data, {});
    ObjectProbabilityMap::Options opt;
    opt.centre_noise_floor = 0.35;
    const ObjectProbabilityMap centre(data, opt);
    for (std::size_t i = 0; i < data.objects.size(); ++i) {
        const auto& o = data.objects[i];
        const auto expected = model::makeObjectDistribution(
            o.box, model::withoutFootprint(*data.noiseOf(o), o.box, o.noiseSource(), 0.35), o.noiseSource());
        const auto& a = as_is.distribution(i);
        const auto& c = centre.distribution(i);
        EXPECT_NEAR(c.sigma_x_m, expected.sigma_x_m, 1e-12) << "object " << o.id;
        EXPECT_NEAR(c.sigma_y_m, expected.sigma_y_m, 1e-12) << "object " << o.id;
        EXPECT_LT(c.sigma_min_m, a.sigma_min_m) << "object " << o.id;
        EXPECT_TRUE(c.mean_world_m.isApprox(a.mean_world_m)) << "object " << o.id;
        EXPECT_GT(c.probability(c.mean_world_m.x(), c.mean_world_m.y()), 0.99);
    }
    opt.centre_noise_floor = 1.5;
    EXPECT_THROW(ObjectProbabilityMap(data, opt), std::invalid_argument);
}

}  // namespace
}  // namespace simp::maps
