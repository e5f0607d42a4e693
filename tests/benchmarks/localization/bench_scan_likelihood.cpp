// The LiDAR sensor model of `simp-localize --method lidar|simp+lidar` (doc/lidar.md): one simulated
// 1081-beam scan (Hokuyo UTM-30LX defaults) weighed for 5000 particles with MRPT's likelihood field on
// the built-in office's floor plan, every beam (decimation 1) or every n-th (doc/performance.md).
#include <benchmark/benchmark.h>
#include <simp/localization/ScanLikelihood.h>
#include <simp/sim/LidarSimulator.h>
#include <simp/sim/Office.h>

#include <vector>

namespace {

constexpr std::size_t kParticles = 5000;

struct ScanSetup {
    simp::world::World world = simp::sim::generateOffice(simp::sim::OfficeParams{}, 1);
    mrpt::obs::CObservation2DRangeScan scan;
    std::vector<mrpt::math::TPose2D> poses;

    ScanSetup() {
        simp::sim::LidarSimulator lidar(world, simp::sim::LidarParams{});
        simp::sim::Rng rng(2);
        const auto& g = world.floorplan;
        // particles spread over the free space (global localization, the expensive case)
        while (poses.size() < kParticles) {
            const double x = rng.uniform(g.getXMin(), g.getXMax()), y = rng.uniform(g.getYMin(), g.getYMax());
            if (g.getPos(x, y) > 0.5f) poses.push_back({x, y, rng.uniform(-M_PI, M_PI)});
        }
        scan = lidar.scan(poses.front(), {}, 0.0, rng);
    }
};

const ScanSetup& setup() {
    static const ScanSetup s;
    return s;
}

void BM_ScanLikelihood5000Particles(benchmark::State& state) {
    const auto& s = setup();
    simp::localization::LidarModelOptions o;
    o.decimation = static_cast<int>(state.range(0));
    simp::localization::ScanLikelihood model(s.world.floorplan, o);
    std::vector<double> log(kParticles);
    model.logLikelihoods(s.scan, s.poses.data(), kParticles, log.data());  // fills MRPT's likelihood cache
    for (auto _ : state) {
        model.logLikelihoods(s.scan, s.poses.data(), kParticles, log.data());
        benchmark::DoNotOptimize(log.data());
    }
    state.counters["beams"] = static_cast<double>((s.scan.getScanSize() + static_cast<std::size_t>(o.decimation) - 1) /
                                                  static_cast<std::size_t>(o.decimation));
    state.counters["ns_per_particle"] =
        benchmark::Counter(static_cast<double>(kParticles), benchmark::Counter::kIsIterationInvariantRate |
                                                                benchmark::Counter::kInvert);
}
BENCHMARK(BM_ScanLikelihood5000Particles)->Arg(1)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);

/// Tracking: 5000 particles within +-0.2 m / +-0.05 rad of the scan's pose, the shipped decimation; beam
/// skipping off (0) or on (1, the default): its cost is the check of every return at <= 500 particles.
void BM_ScanLikelihoodTracking5000Particles(benchmark::State& state) {
    const auto& s = setup();
    simp::localization::LidarModelOptions o;
    if (state.range(0) == 0) o.beam_skip_threshold = 0;
    simp::localization::ScanLikelihood model(s.world.floorplan, o);
    simp::sim::Rng rng(4);
    const auto& truth = s.poses.front();
    std::vector<mrpt::math::TPose2D> poses(kParticles);
    for (auto& p : poses)
        p = {truth.x + rng.uniform(-0.2, 0.2), truth.y + rng.uniform(-0.2, 0.2), truth.phi + rng.uniform(-0.05, 0.05)};
    std::vector<double> log(kParticles);
    model.logLikelihoods(s.scan, poses.data(), kParticles, log.data());
    for (auto _ : state) {
        model.logLikelihoods(s.scan, poses.data(), kParticles, log.data());
        benchmark::DoNotOptimize(log.data());
    }
    state.counters["skipped"] = static_cast<double>(model.lastSkipped());
}
BENCHMARK(BM_ScanLikelihoodTracking5000Particles)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
