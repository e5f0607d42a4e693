/// Tests of simp/geometry/OrientedRect.h: the rectangle's intersection area and the separating-axis test
/// must agree with the generic convex clipping of ConvexPolygon.h (intersectionArea) up to
/// rounding, on hand-made edge cases and on many random pairs.
#include <simp/geometry/ConvexPolygon.h>
#include <simp/geometry/OrientedRect.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace simp::geometry {
namespace {

// Rounding tolerance relative to the larger area (<= the union): an IoU tolerance of 1e-12.
constexpr double kRel = 1e-12;

OrientedRect rect(double x, double y, double yaw, double lx, double ly) {
    OrientedRect r;
    r.center = {x, y};
    r.c = std::cos(yaw);
    r.s = std::sin(yaw);
    r.hx = lx / 2;
    r.hy = ly / 2;
    return r;
}

/// p expressed in r's frame (what the sensor model clips).
ConvexPolygon toLocal(const ConvexPolygon& p, const OrientedRect& r) {
    ConvexPolygon out;
    for (std::size_t i = 0; i < p.n; ++i) out.push(r.toLocal(p.v[i]));
    return out;
}

ConvexPolygon reversed(const ConvexPolygon& p) {
    ConvexPolygon r;
    for (std::size_t i = p.n; i-- > 0;) r.push(p.v[i]);
    return r;
}

/// Fast path (clip in r's frame) against the generic clipping in the world, and the
/// separating-axis test against the clipped area when p is a rectangle.
void expectAgrees(const OrientedRect& r, const ConvexPolygon& p, const char* what) {
    // The generic clipping, both polygons moved next to the origin: in world coordinates (up
    // to 20 m here) its shoelace sum alone has an absolute error of ~eps x 20^2 = 1e-13 m^2,
    // more than 1e-12 of a small object's area; the area is translation-invariant.
    const ConvexPolygon p0 = p.transformed(1.0, 0.0, -r.center);
    const ConvexPolygon r0 = r.polygon().transformed(1.0, 0.0, -r.center);
    const double generic = intersectionArea(p0, r0);
    EXPECT_NEAR(intersectionArea(p, r.polygon()), generic, 1e-12 * std::max(1.0, r.center.squaredNorm())) << what;
    const double fast = intersectionAreaWithAlignedRect(toLocal(p, r), r.hx, r.hy);
    const double scale = std::max(r.area(), p.area());
    EXPECT_NEAR(fast, generic, kRel * scale) << what;
    EXPECT_NEAR(intersectionAreaWithAlignedRect(toLocal(reversed(p), r), r.hx, r.hy), generic, kRel * scale)
        << what << " (clockwise)";
    if (const auto q = asRectangle(p)) {
        OrientedRect local = *q;  // q in r's frame
        local.center = r.toLocal(q->center);
        local.c = r.c * q->c + r.s * q->s;
        local.s = r.c * q->s - r.s * q->c;
        EXPECT_NEAR(intersectionAreaWithAlignedRect(local, r.hx, r.hy), generic, kRel * scale) << what << " (rectangle)";
        if (separated(r, *q)) {
            EXPECT_LE(generic, kRel * scale) << what << ": separated but overlapping";
        }
        EXPECT_EQ(separated(r, *q), separated(*q, r)) << what;
    }
}

TEST(OrientedRect, PolygonAndAsRectangleRoundTrip) {
    const OrientedRect r = rect(3.0, -2.0, 0.7, 1.6, 0.4);
    const ConvexPolygon p = r.polygon();
    EXPECT_NEAR(p.area(), r.area(), 1e-12);
    EXPECT_NEAR(makeRectangle({3.0, -2.0}, 1.6, 0.4, 0.7).area(), p.area(), 1e-12);
    for (const ConvexPolygon& q : {p, reversed(p), makeRectangle({3.0, -2.0}, 1.6, 0.4, 0.7)}) {
        const auto back = asRectangle(q);
        ASSERT_TRUE(back.has_value());
        EXPECT_NEAR(back->area(), r.area(), 1e-12);
        EXPECT_TRUE(back->center.isApprox(r.center, 1e-14));
        EXPECT_NEAR(intersectionArea(back->polygon(), p), r.area(), 1e-12);  // the same solid
    }
    const Eigen::Vector2d local = r.toLocal(r.center + Eigen::Vector2d(r.c, r.s) * 0.5);
    EXPECT_NEAR(local.x(), 0.5, 1e-15);
    EXPECT_NEAR(local.y(), 0.0, 1e-15);
}

TEST(OrientedRect, AsRectangleRejectsOtherShapes) {
    ConvexPolygon parallelogram, trapezoid, triangle, segment, five;
    for (const auto& v : {Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 0), Eigen::Vector2d(3, 1), Eigen::Vector2d(1, 1)})
        parallelogram.push(v);
    for (const auto& v : {Eigen::Vector2d(0, 0), Eigen::Vector2d(3, 0), Eigen::Vector2d(2, 1), Eigen::Vector2d(1, 1)})
        trapezoid.push(v);
    for (const auto& v : {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)}) triangle.push(v);
    for (const auto& v : {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 0)})
        segment.push(v);  // zero width: degenerate, left to the generic path
    for (int i = 0; i < 5; ++i) five.push({std::cos(i * 1.2566), std::sin(i * 1.2566)});
    for (const auto& p : {parallelogram, trapezoid, triangle, segment, five, ConvexPolygon{}})
        EXPECT_FALSE(asRectangle(p).has_value());
    // A corner moved by more than rounding is not a rectangle.
    ConvexPolygon almost = makeRectangle({0, 0}, 1.0, 0.5, 0.3);
    almost.v[2].x() += 1e-9;
    EXPECT_FALSE(asRectangle(almost).has_value());
}

TEST(OrientedRect, HandMadeCases) {
    const OrientedRect r = rect(1.0, 2.0, 0.4, 2.0, 1.0);
    const Eigen::Vector2d ux(r.c, r.s), uy(-r.s, r.c);
    const auto moved = [&](double along_x, double along_y, double yaw, double lx, double ly) {
        const Eigen::Vector2d c = r.center + along_x * ux + along_y * uy;
        return makeRectangle(c, lx, ly, 0.4 + yaw);
    };
    // Identical, contained, containing.
    EXPECT_NEAR(intersectionAreaWithAlignedRect(toLocal(r.polygon(), r), r.hx, r.hy), 2.0, 1e-12);
    EXPECT_NEAR(intersectionAreaWithAlignedRect(toLocal(moved(0.2, 0.1, 0.3, 0.5, 0.3), r), r.hx, r.hy), 0.15, 1e-12);
    EXPECT_NEAR(intersectionAreaWithAlignedRect(toLocal(moved(0.1, 0.0, 0.0, 4.0, 3.0), r), r.hx, r.hy), 2.0, 1e-12);
    // Half overlap along x; disjoint; sharing an edge; sharing a corner.
    EXPECT_NEAR(intersectionAreaWithAlignedRect(toLocal(moved(1.0, 0.0, 0.0, 2.0, 1.0), r), r.hx, r.hy), 1.0, 1e-12);
    EXPECT_EQ(intersectionAreaWithAlignedRect(toLocal(moved(5.0, 0.0, 0.0, 2.0, 1.0), r), r.hx, r.hy), 0.0);
    EXPECT_NEAR(intersectionAreaWithAlignedRect(toLocal(moved(2.0, 0.0, 0.0, 2.0, 1.0), r), r.hx, r.hy), 0.0, 1e-12);
    EXPECT_NEAR(intersectionAreaWithAlignedRect(toLocal(moved(2.0, 1.0, 0.0, 2.0, 1.0), r), r.hx, r.hy), 0.0, 1e-12);
    // A diamond whose tip pokes through the middle of the right edge by 0.1: a triangle of 0.1 x 0.2 / 2.
    ConvexPolygon diamond;
    for (const auto& v : {Eigen::Vector2d(0.9, 0), Eigen::Vector2d(1.4, -0.5), Eigen::Vector2d(1.9, 0), Eigen::Vector2d(1.4, 0.5)})
        diamond.push(v);
    EXPECT_NEAR(intersectionAreaWithAlignedRect(diamond, 1.0, 0.5), 0.01, 1e-12);
    // Degenerate inputs: fewer than 3 vertices, zero-area polygon, zero-size rectangle.
    ConvexPolygon two;
    two.push({0, 0});
    two.push({1, 1});
    EXPECT_EQ(intersectionAreaWithAlignedRect(two, 1.0, 1.0), 0.0);
    ConvexPolygon flat;
    for (const auto& v : {Eigen::Vector2d(-2, 0), Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 0)}) flat.push(v);
    EXPECT_EQ(intersectionAreaWithAlignedRect(flat, 1.0, 1.0), 0.0);
    EXPECT_EQ(intersectionAreaWithAlignedRect(diamond, 0.0, 0.5), 0.0);
    for (const auto& p : {moved(0.2, 0.1, 0.3, 0.5, 0.3), moved(1.0, 0.0, 0.0, 2.0, 1.0), moved(2.0, 0.0, 0.0, 2.0, 1.0),
                          moved(2.0, 1.0, 0.0, 2.0, 1.0), moved(0.0, 0.0, 0.0, 2.0, 1.0), moved(1.5, 0.9, 0.785, 0.5, 0.5)})
        expectAgrees(r, p, "hand-made");
    // Separating axes: edge-sharing and corner-sharing rectangles are separated; a rotated
    // square near a corner whose bounding boxes overlap is separated only by its own axis.
    EXPECT_TRUE(separated(r, *asRectangle(moved(2.0, 0.0, 0.0, 2.0, 1.0))));
    EXPECT_FALSE(separated(r, *asRectangle(moved(1.9, 0.0, 0.0, 2.0, 1.0))));
    const OrientedRect a = rect(0, 0, 0, 2, 2), b = rect(1.75, 1.75, M_PI / 4, 1, 1);
    EXPECT_TRUE(separated(a, b));
    EXPECT_TRUE(separated(b, a));
    EXPECT_LE(intersectionArea(a.polygon(), b.polygon()), 1e-15);
}

/// The rectangle overload turns `a` into the first quadrant and clips a box within ~0.01 rad of the
/// axes: exact quarter turns (cos or sin exactly 0, where 1/cos or 1/sin is infinite), tiny angles,
/// angles about that threshold, and every quadrant, against the generic clipping.
TEST(OrientedRect, QuarterTurnsAndNearlyAlignedBoxesAgreeWithGenericClipping) {
    const double hx = 1.2, hy = 0.7;
    const OrientedRect aligned = rect(0, 0, 0, 2 * hx, 2 * hy);
    for (const double base : {0.0, M_PI / 2, M_PI, -M_PI / 2})
        for (const double tiny : {0.0, 1e-14, -1e-13, 1e-10, -1e-6, 0.0099, 0.0101, -0.0101, 0.02, 0.3})
            for (const Eigen::Vector2d& c : {Eigen::Vector2d(0.4, -0.3), Eigen::Vector2d(1.5, 0.2), Eigen::Vector2d(-0.2, 0.9)}) {
                OrientedRect a = rect(c.x(), c.y(), base + tiny, 1.6, 0.5);
                if (tiny == 0.0) {  // exact quarter turns, as a sensor model's rotation can give them
                    const int k = static_cast<int>(std::lround(base / (M_PI / 2)));
                    a.c = k == 0 ? 1.0 : (k == 2 ? -1.0 : 0.0);
                    a.s = k == 1 ? 1.0 : (k == -1 ? -1.0 : 0.0);
                }
                const double generic = intersectionArea(a.polygon(), aligned.polygon());
                EXPECT_NEAR(intersectionAreaWithAlignedRect(a, hx, hy), generic, kRel * aligned.area())
                    << "turn " << base << " + " << tiny << " at " << c.transpose();
            }
}

/// Random pairs in the sensor model's range (world coordinates up to 20 m, sides 0.05 to
/// 3 m), including the cases a random draw almost never hits: equal, touching, nested.
TEST(OrientedRect, RandomPairsAgreeWithGenericClipping) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> upos(-20, 20), uoff(-2, 2), uyaw(-M_PI, M_PI), uside(0.05, 3.0), u01(0, 1);
    int separated_count = 0, overlapping = 0;
    for (int i = 0; i < 20000; ++i) {
        const OrientedRect r = rect(upos(rng), upos(rng), uyaw(rng), uside(rng), uside(rng));
        const Eigen::Vector2d ux(r.c, r.s), uy(-r.s, r.c);
        ConvexPolygon p;
        switch (i % 6) {
            case 0:
            case 1:  // any rectangle nearby
                p = makeRectangle(r.center + Eigen::Vector2d(uoff(rng), uoff(rng)), uside(rng), uside(rng), uyaw(rng));
                break;
            case 2: {  // same yaw, touching along x or y (or at a corner)
                const double lx = uside(rng), ly = uside(rng);
                const double ax = (i % 4 < 2 ? 1 : -1) * (r.hx + lx / 2), ay = u01(rng) < 0.5 ? (r.hy + ly / 2) : uoff(rng) * 0.1;
                p = makeRectangle(r.center + ax * ux + ay * uy, lx, ly, std::atan2(r.s, r.c));
                break;
            }
            case 3:  // nested: a small one inside, or a big one around
                p = u01(rng) < 0.5 ? makeRectangle(r.center + 0.2 * std::min(r.hx, r.hy) * Eigen::Vector2d(u01(rng), u01(rng)),
                                                   0.5 * r.hx, 0.5 * r.hy, uyaw(rng))
                                   : makeRectangle(r.center, 4.5 * (r.hx + r.hy), 4.5 * (r.hx + r.hy), uyaw(rng));
                break;
            case 4: {  // the same solid, its vertices numbered from another corner (turned by k x 90 deg)
                const int k = static_cast<int>(4 * u01(rng));
                const double lx = 2 * (k % 2 ? r.hy : r.hx), ly = 2 * (k % 2 ? r.hx : r.hy);
                p = makeRectangle(r.center, lx, ly, std::atan2(r.s, r.c) + M_PI / 2 * k);
                break;
            }
            default: {  // a random convex polygon (hull of up to 8 points): the non-rectangle input
                Eigen::Vector2d pts[8];
                const std::size_t n = 3 + static_cast<std::size_t>(6 * u01(rng));
                const Eigen::Vector2d c = r.center + Eigen::Vector2d(uoff(rng), uoff(rng));
                for (std::size_t k = 0; k < n; ++k) pts[k] = c + Eigen::Vector2d(uoff(rng), uoff(rng)) * 0.7;
                p = convexHull(pts, n);
            }
        }
        if (p.n < 3) continue;
        expectAgrees(r, p, ("random pair " + std::to_string(i)).c_str());
        if (const auto q = asRectangle(p)) {
            if (separated(r, *q)) ++separated_count;
            else if (intersectionArea(p, r.polygon()) > 0.0) ++overlapping;
        }
        if (::testing::Test::HasFailure()) break;  // one report, not thousands
    }
    // Both branches exercised many times.
    EXPECT_GT(separated_count, 1000);
    EXPECT_GT(overlapping, 2000);
}

}  // namespace
}  // namespace simp::geometry
