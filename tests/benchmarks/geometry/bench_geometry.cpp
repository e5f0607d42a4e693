/// Benchmarks of libs/geometry: the polygon IoU of the sensor model's hot path
/// (Eq. iouscore, per particle x detection), the 3D IoU of the association cost
/// (Eq. costfunc), the assignment and the rotation average of the map update.
#include <simp/geometry/Box3DIoU.h>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/geometry/Footprint.h>
#include <simp/geometry/Hungarian.h>
#include <simp/geometry/OrientedRect.h>
#include <simp/geometry/RotationAverage.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace simp::geometry;

Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<double> n01;
    return Eigen::Quaterniond(n01(rng), n01(rng), n01(rng), n01(rng)).normalized().toRotationMatrix();
}

/// Two partially overlapping rotated rectangles (an 8-vertex intersection).
void BM_PolygonIoU_Rectangles(benchmark::State& state) {
    const ConvexPolygon a = makeRectangle({0.0, 0.0}, 1.2, 0.6, 0.3);
    const ConvexPolygon b = makeRectangle({0.2, 0.1}, 1.0, 0.8, 1.1);
    for (auto _ : state) {
        benchmark::DoNotOptimize(a);
        benchmark::DoNotOptimize(b);
        benchmark::DoNotOptimize(iou(a, b));
    }
}
BENCHMARK(BM_PolygonIoU_Rectangles);

/// Many different overlapping pairs, so that branch prediction cannot learn one input:
/// random rectangles of 0.3..1.5 m sides within 1 m of each other (most overlap).
void BM_PolygonIoU_RandomPairs(benchmark::State& state) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> side(0.3, 1.5), offset(-0.5, 0.5), yaw(-M_PI, M_PI);
    constexpr std::size_t kPairs = 1024;
    std::vector<ConvexPolygon> a, b;
    for (std::size_t i = 0; i < kPairs; ++i) {
        a.push_back(makeRectangle({0.0, 0.0}, side(rng), side(rng), yaw(rng)));
        b.push_back(makeRectangle({offset(rng), offset(rng)}, side(rng), side(rng), yaw(rng)));
    }
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(iou(a[i], b[i]));
        i = (i + 1) % kPairs;
    }
}
BENCHMARK(BM_PolygonIoU_RandomPairs);

/// What the sensor model does per particle x detection: move the detection's footprint
/// from the robot frame into the world with the particle's pose, then IoU with a map footprint.
void BM_PolygonIoU_TransformAndIoU(benchmark::State& state) {
    const ConvexPolygon detection = makeRectangle({1.5, 0.2}, 0.9, 0.5, 0.2);
    const ConvexPolygon map_object = makeRectangle({3.6, 2.1}, 1.0, 0.6, 0.9);
    const double yaw = 0.7, c = std::cos(yaw), s = std::sin(yaw);
    const Eigen::Vector2d t(2.0, 1.0);
    for (auto _ : state) {
        benchmark::DoNotOptimize(detection);
        const ConvexPolygon moved = detection.transformed(c, s, t);
        benchmark::DoNotOptimize(iou(moved, map_object));
    }
}
BENCHMARK(BM_PolygonIoU_TransformAndIoU);

/// Footprint of a tilted box: 8 corners, hull (a hexagon).
void BM_Footprint_Tilted(benchmark::State& state) {
    std::mt19937_64 rng(1);
    Box3D box;
    box.size = {0.8, 0.5, 1.1};
    box.R = randomRotation(rng);
    for (auto _ : state) {
        benchmark::DoNotOptimize(box);
        benchmark::DoNotOptimize(footprint(box));
    }
}
BENCHMARK(BM_Footprint_Tilted);

/// iou3D of two upright boxes (fast path: footprint IoU x height overlap).
void BM_IoU3D_Upright(benchmark::State& state) {
    const Box3D a = makeUprightBox({0.0, 0.0, 0.4}, {1.2, 0.6, 0.8}, 0.3);
    const Box3D b = makeUprightBox({0.2, 0.1, 0.5}, {1.0, 0.8, 0.9}, 1.1);
    for (auto _ : state) {
        benchmark::DoNotOptimize(a);
        benchmark::DoNotOptimize(iou3D(a, b));
    }
}
BENCHMARK(BM_IoU3D_Upright);

/// iou3D of two overlapping boxes with general rotations (polyhedron clipping).
void BM_IoU3D_General(benchmark::State& state) {
    std::mt19937_64 rng(2);
    Box3D a, b;
    a.size = {1.2, 0.6, 0.8};
    a.R = randomRotation(rng);
    b.center = {0.2, 0.1, 0.1};
    b.size = {1.0, 0.8, 0.9};
    b.R = randomRotation(rng);
    for (auto _ : state) {
        benchmark::DoNotOptimize(a);
        benchmark::DoNotOptimize(iou3D(a, b));
    }
}
BENCHMARK(BM_IoU3D_General);

/// Assignment of n detections to 2n map objects with random costs.
void BM_Hungarian(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Eigen::MatrixXd cost(n, 2 * n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < 2 * n; ++c) cost(r, c) = u(rng);
    for (auto _ : state) benchmark::DoNotOptimize(solveAssignment(cost));
    state.SetComplexityN(n);
}
BENCHMARK(BM_Hungarian)->RangeMultiplier(4)->Range(4, 256)->Complexity(benchmark::oNCubed);

/// The map update of one merged object: two rotations weighted by their n_match.
void BM_AverageRotations_Two(benchmark::State& state) {
    std::mt19937_64 rng(4);
    const std::vector<Eigen::Matrix3d> Rs = {randomRotation(rng), randomRotation(rng)};
    const std::vector<double> w = {5.0, 1.0};
    for (auto _ : state) benchmark::DoNotOptimize(averageRotations(Rs, w));
}
BENCHMARK(BM_AverageRotations_Two);

}  // namespace

namespace {

/// The sensor model's tracking case in a map object's frame: a rectangle of 0.3..1.5 m sides
/// within 0.3 m and 0.3 rad of the aligned one it is intersected with (nearly all overlap).
struct TrackingPairs {
    static constexpr std::size_t kPairs = 1024;
    std::vector<OrientedRect> a;
    std::vector<ConvexPolygon> a_polygon;
    std::vector<double> hx, hy;
    TrackingPairs() {
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> side(0.3, 1.5), offset(-0.3, 0.3), yaw(-0.3, 0.3);
        for (std::size_t i = 0; i < kPairs; ++i) {
            const double lx = side(rng), ly = side(rng), phi = yaw(rng);
            OrientedRect r;
            r.center = {offset(rng), offset(rng)};
            r.c = std::cos(phi);
            r.s = std::sin(phi);
            r.hx = 0.5 * lx * (1.0 + 0.2 * offset(rng));
            r.hy = 0.5 * ly;
            a.push_back(r);
            a_polygon.push_back(r.polygon());
            hx.push_back(0.5 * lx);
            hy.push_back(0.5 * ly);
        }
    }
};
const TrackingPairs& trackingPairs() {
    static const TrackingPairs pairs;
    return pairs;
}

void BM_AlignedRect_Rectangle(benchmark::State& state) {
    const auto& p = trackingPairs();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(intersectionAreaWithAlignedRect(p.a[i], p.hx[i], p.hy[i]));
        i = (i + 1) % TrackingPairs::kPairs;
    }
}
BENCHMARK(BM_AlignedRect_Rectangle);

void BM_AlignedRect_Polygon(benchmark::State& state) {
    const auto& p = trackingPairs();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(intersectionAreaWithAlignedRect(p.a_polygon[i], p.hx[i], p.hy[i]));
        i = (i + 1) % TrackingPairs::kPairs;
    }
}
BENCHMARK(BM_AlignedRect_Polygon);

/// The same pairs by the generic clipping (the aligned rectangles built outside the loop).
void BM_AlignedRect_Generic(benchmark::State& state) {
    const auto& p = trackingPairs();
    std::vector<ConvexPolygon> b;
    for (std::size_t i = 0; i < TrackingPairs::kPairs; ++i) b.push_back(makeRectangle({0, 0}, 2 * p.hx[i], 2 * p.hy[i], 0));
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(intersectionArea(p.a_polygon[i], b[i]));
        i = (i + 1) % TrackingPairs::kPairs;
    }
}
BENCHMARK(BM_AlignedRect_Generic);

}  // namespace
