/// Tests of simp/geometry/ConvexPolygon.h: area, hull and the exact clipping IoU
/// on cases whose value is computed by hand.
#include <simp/geometry/ConvexPolygon.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace simp::geometry {
namespace {

constexpr double kTol = 1e-12;

ConvexPolygon square(double x0, double y0, double x1, double y1) {
    ConvexPolygon p;
    p.push({x0, y0});
    p.push({x1, y0});
    p.push({x1, y1});
    p.push({x0, y1});
    return p;
}

ConvexPolygon reversed(const ConvexPolygon& p) {
    ConvexPolygon r;
    for (std::size_t i = p.n; i-- > 0;) r.push(p.v[i]);
    return r;
}

/// Regular n-gon of circumradius r centred at the origin, first vertex at angle phase.
ConvexPolygon regular(std::size_t n, double r, double phase) {
    ConvexPolygon p;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = phase + 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
        p.push({r * std::cos(a), r * std::sin(a)});
    }
    return p;
}

TEST(ConvexPolygon, AreaAndCentroid) {
    const ConvexPolygon r = square(1, 2, 4, 4);  // 3 x 2
    EXPECT_NEAR(r.area(), 6.0, kTol);
    EXPECT_NEAR(reversed(r).area(), 6.0, kTol);  // clockwise: area still >= 0
    EXPECT_TRUE(r.centroid().isApprox(Eigen::Vector2d(2.5, 3.0)));
    ConvexPolygon tri;
    tri.push({0, 0});
    tri.push({4, 0});
    tri.push({0, 3});
    EXPECT_NEAR(tri.area(), 6.0, kTol);
    EXPECT_TRUE(tri.centroid().isApprox(Eigen::Vector2d(4.0 / 3.0, 1.0)));
    ConvexPolygon segment;
    segment.push({0, 0});
    segment.push({1, 1});
    EXPECT_EQ(segment.area(), 0.0);
    Eigen::Vector2d lo, hi;
    r.bounds(lo, hi);
    EXPECT_TRUE(lo.isApprox(Eigen::Vector2d(1, 2)));
    EXPECT_TRUE(hi.isApprox(Eigen::Vector2d(4, 4)));
}

TEST(ConvexPolygon, MakeRectangleAndTransform) {
    const ConvexPolygon r = makeRectangle({1, -1}, 4.0, 2.0, M_PI / 6);
    ASSERT_EQ(r.n, 4u);
    EXPECT_NEAR(r.area(), 8.0, kTol);
    EXPECT_TRUE(r.centroid().isApprox(Eigen::Vector2d(1, -1)));
    // First vertex = center - (c, s) * 2 - (-s, c) * 1.
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    EXPECT_NEAR((r.v[0] - Eigen::Vector2d(1 - 2 * c + s, -1 - 2 * s - c)).norm(), 0.0, kTol);
    // A rigid motion (rotation by 90 deg about the origin, then translation) keeps the area.
    const ConvexPolygon t = r.transformed(std::cos(M_PI / 2), std::sin(M_PI / 2), {0.5, 0.0});
    EXPECT_NEAR(t.area(), 8.0, kTol);
    EXPECT_TRUE(t.centroid().isApprox(Eigen::Vector2d(1.5, 1.0)));  // (1, -1) rotated 90 deg + (0.5, 0)
}

TEST(ConvexPolygon, PushBeyondCapacityThrows) {
    ConvexPolygon p;
    for (std::size_t i = 0; i < ConvexPolygon::kMaxVertices; ++i) p.push({double(i), 0.0});
    EXPECT_THROW(p.push({0.0, 1.0}), std::length_error);
}

TEST(ConvexPolygon, ConvexHullDropsInteriorCollinearAndDuplicatePoints) {
    const Eigen::Vector2d pts[] = {{0, 0}, {1, 1}, {2, 0}, {1, 0},  // (1,0) collinear on the bottom edge
                                   {2, 2}, {0, 2}, {0.5, 1.5}, {2, 2}};  // interior and duplicate
    const ConvexPolygon h = convexHull(pts, 8);
    ASSERT_EQ(h.n, 4u);
    EXPECT_NEAR(h.area(), 4.0, kTol);
    // Counter-clockwise from the lowest-leftmost point.
    EXPECT_TRUE(h.v[0].isApprox(Eigen::Vector2d(0, 0)));
    EXPECT_TRUE(h.v[1].isApprox(Eigen::Vector2d(2, 0)));
    EXPECT_TRUE(h.v[2].isApprox(Eigen::Vector2d(2, 2)));
    EXPECT_TRUE(h.v[3].isApprox(Eigen::Vector2d(0, 2)));
    EXPECT_EQ(convexHull(pts, 0).n, 0u);
    EXPECT_EQ(convexHull(pts, 1).n, 1u);
    EXPECT_EQ(convexHull(pts, 2).n, 2u);
    Eigen::Vector2d many[ConvexPolygon::kMaxVertices + 1];
    for (auto& p : many) p.setZero();
    EXPECT_THROW(convexHull(many, ConvexPolygon::kMaxVertices + 1), std::length_error);
}

TEST(ConvexPolygonIoU, Identical) {
    const ConvexPolygon a = makeRectangle({0.3, -0.2}, 2.0, 0.7, 0.4);
    EXPECT_NEAR(iou(a, a), 1.0, kTol);
    EXPECT_NEAR(intersectionArea(a, a), 1.4, kTol);
}

TEST(ConvexPolygonIoU, Disjoint) {
    EXPECT_EQ(iou(square(0, 0, 1, 1), square(3, 0, 4, 1)), 0.0);
    // Bounding boxes overlap but the rotated rectangles do not.
    EXPECT_EQ(iou(makeRectangle({0, 0}, 4, 0.2, M_PI / 4), makeRectangle({1.5, -1.5}, 4, 0.2, M_PI / 4)), 0.0);
}

TEST(ConvexPolygonIoU, Contained) {
    // A 1 x 1 square inside a 2 x 2 square: inter = 1, union = 4.
    EXPECT_NEAR(iou(square(0.5, 0.5, 1.5, 1.5), square(0, 0, 2, 2)), 0.25, kTol);
    EXPECT_NEAR(iou(square(0, 0, 2, 2), square(0.5, 0.5, 1.5, 1.5)), 0.25, kTol);
}

TEST(ConvexPolygonIoU, Rotated45Degrees) {
    // Unit square vs the same square rotated 45 deg about its centre. The rotated square is
    // |x| + |y| <= sqrt(2)/2, cutting from each corner of the unit square a right isosceles
    // triangle of legs 1 - sqrt(2)/2: the four cut 2 (1 - sqrt(2)/2)^2 = 3 - 2 sqrt(2).
    // inter = 1 - (3 - 2 sqrt(2)) = 2 sqrt(2) - 2, union = 2 - inter = 4 - 2 sqrt(2),
    // IoU = (2 sqrt(2) - 2) / (4 - 2 sqrt(2)) = 1 / sqrt(2).
    const ConvexPolygon a = makeRectangle({0, 0}, 1, 1, 0.0);
    const ConvexPolygon b = makeRectangle({0, 0}, 1, 1, M_PI / 4);
    EXPECT_NEAR(intersectionArea(a, b), 2 * std::sqrt(2.0) - 2, kTol);
    EXPECT_NEAR(iou(a, b), 1 / std::sqrt(2.0), kTol);
}

TEST(ConvexPolygonIoU, TouchingEdgeAndCornerGiveZero) {
    EXPECT_EQ(iou(square(0, 0, 1, 1), square(1, 0, 2, 1)), 0.0);  // shared edge
    EXPECT_EQ(iou(square(0, 0, 1, 1), square(1, 1, 2, 2)), 0.0);  // shared corner
    EXPECT_EQ(iou(square(0, 0, 1, 1), square(1, 0.5, 2, 3)), 0.0);  // partly shared edge
}

TEST(ConvexPolygonIoU, PartialOverlap) {
    // 2 x 2 squares, the second shifted by (1, 0.5): inter = 1 x 1.5, union = 8 - 1.5, IoU = 3/13.
    const ConvexPolygon a = square(0, 0, 2, 2), b = square(1, 0.5, 3, 2.5);
    EXPECT_NEAR(intersectionArea(a, b), 1.5, kTol);
    EXPECT_NEAR(iou(a, b), 3.0 / 13.0, kTol);
    EXPECT_NEAR(iou(b, a), 3.0 / 13.0, kTol);
}

TEST(ConvexPolygonIoU, EitherVertexOrderGivesTheSameResult) {
    const ConvexPolygon a = square(0, 0, 2, 2), b = square(1, 0.5, 3, 2.5);
    EXPECT_NEAR(iou(a, reversed(b)), 3.0 / 13.0, kTol);
    EXPECT_NEAR(iou(reversed(a), b), 3.0 / 13.0, kTol);
    EXPECT_NEAR(iou(reversed(a), reversed(b)), 3.0 / 13.0, kTol);
    EXPECT_NEAR(intersectionArea(a, reversed(b)), 1.5, kTol);
}

TEST(ConvexPolygonIoU, IntersectionWithMoreVerticesThanCapacity) {
    // Two regular 16-gons (circumradius r), one rotated by pi/16: their intersection is a
    // regular 32-gon whose edges are tangent to the common incircle of radius a = r cos(pi/16),
    // of area 32 a^2 tan(pi/32). It has more vertices than ConvexPolygon::kMaxVertices.
    const double r = 1.3;
    const ConvexPolygon a = regular(16, r, 0.0), b = regular(16, r, M_PI / 16);
    const double apothem = r * std::cos(M_PI / 16);
    const double expected = 32 * apothem * apothem * std::tan(M_PI / 32);
    EXPECT_NEAR(intersectionArea(a, b), expected, 1e-12);
    EXPECT_NEAR(iou(a, b), expected / (2 * a.area() - expected), 1e-12);
}

TEST(ConvexPolygonIoU, DegenerateAndNaNInput) {
    ConvexPolygon segment;
    segment.push({0, 0});
    segment.push({1, 1});
    EXPECT_EQ(iou(segment, square(0, 0, 1, 1)), 0.0);
    EXPECT_EQ(iou(ConvexPolygon{}, square(0, 0, 1, 1)), 0.0);
    ConvexPolygon flat;  // three collinear points: zero area
    flat.push({0, 0});
    flat.push({1, 0});
    flat.push({2, 0});
    EXPECT_EQ(iou(flat, square(0, -1, 2, 1)), 0.0);
    ConvexPolygon nan = square(0, 0, 1, 1);
    nan.v[2].x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(std::isnan(iou(nan, square(0, 0, 1, 1))));
}

}  // namespace
}  // namespace simp::geometry
