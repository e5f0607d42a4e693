// One whole MCL step (MRPT's prediction with the odometry action, weighing every particle with
// the paper's sensor model over K = 8 detections, resampling) for 5000 particles, on the
// simp-office map (doc/performance.md). "Global": particles spread uniformly over the free
// space before each step (the expensive case while localizing globally); "Tracking": the
// filter left to converge on the true pose.
#include <benchmark/benchmark.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/ObjectMcl.h>
#include <simp/maps/CObjectMap.h>
#include <simp/sim/Office.h>
#include <simp/world/SimpFormat.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace {

constexpr std::size_t kParticles = 5000;
constexpr std::size_t kDetections = 8;

struct Setup {
    simp::world::World world;
    std::shared_ptr<simp::maps::CObjectMap> map;
    mrpt::math::TPose2D truth;
    mrpt::obs::CSensoryFrame frame;
    mrpt::obs::CActionCollection action;
};

Eigen::Isometry3d isometry(const mrpt::poses::CPose3D& p) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = p.getRotationMatrix().asEigen();
    T.translation() = Eigen::Vector3d(p.x(), p.y(), p.z());
    return T;
}

/// Two cameras (forward, backward) with the K/2 map objects nearest to the true pose in each half plane.
void makeFrame(Setup& s) {
    const auto& objs = s.world.objects.objects;
    const mrpt::poses::CPose3D robot(s.truth.x, s.truth.y, 0, s.truth.phi, 0, 0);
    for (int cam = 0; cam < 2; ++cam) {
        auto o = simp::obs::CObservationObjects3D::Create();
        o->setClassNames(s.world.objects.class_names);
        o->sensorLabel = "CAMERA_" + std::to_string(cam);
        o->setCameraPose(simp::obs::cameraPoseOnRobot(0.0, 0.0, 0.63, cam * M_PI));
        const Eigen::Isometry3d camera_T_world = (isometry(robot) * isometry(o->cameraPose())).inverse();
        std::vector<std::pair<double, std::size_t>> ahead;
        for (std::size_t i = 0; i < objs.size(); ++i) {
            const Eigen::Vector3d c = camera_T_world * objs[i].box.center;
            if (c.z() > 0.3) ahead.emplace_back(c.norm(), i);
        }
        std::sort(ahead.begin(), ahead.end());
        for (std::size_t k = 0; k < kDetections / 2 && k < ahead.size(); ++k) {
            const auto& m = objs[ahead[k].second];
            simp::obs::Detection3D d;
            d.class_id = static_cast<std::uint16_t>(m.class_id);
            d.confidence = 0.95f;
            d.box_in_camera = m.box.transformed(camera_T_world);
            o->addDetection(d);
        }
        s.frame.insert(o);
    }
    mrpt::obs::CActionRobotMovement2D mv;
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motion;
    mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0.0, 0.0), motion);
    s.action.insert(mv);
}

Setup& setup() {
    static Setup s = [] {
        Setup x;
        const std::string dir = std::string(SIMP_SHARED_DATA_DIR) + "/simp-office";
        if (std::filesystem::exists(dir + "/global_variance.json")) {
            x.world = simp::world::importSimpMap(dir);
            x.truth = mrpt::math::TPose2D(-9.07765, -7.11326, -3.04342);  // the authors' tracking start
            std::cout << "map: simp-office (" << x.world.objects.objects.size() << " objects)\n";
        } else {
            x.world = simp::sim::generateOffice({}, 1);
            x.truth = mrpt::math::TPose2D(0.5 * (x.world.floorplan.getXMin() + x.world.floorplan.getXMax()),
                                          0.5 * (x.world.floorplan.getYMin() + x.world.floorplan.getYMax()), 0.0);
            std::cout << "map: GENERATED office (" << x.world.objects.objects.size() << " objects; " << dir
                      << " is absent)\n";
        }
        x.map = std::make_shared<simp::maps::CObjectMap>();
        x.map->likelihoodOptions.skip_classes_without_noise = true;
        x.map->setData(x.world.objects);
        makeFrame(x);
        return x;
    }();
    return s;
}

mrpt::bayes::CParticleFilter makeFilter() {
    mrpt::bayes::CParticleFilter pf;
    pf.m_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
    pf.m_options.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
    pf.m_options.BETA = 2.0;  // resample every step: the cost the target includes
    return pf;
}

void resetUniform(simp::localization::ObjectMcl& mcl, const mrpt::maps::COccupancyGridMap2D& grid) {
    mcl.resetUniformFreeSpace(const_cast<mrpt::maps::COccupancyGridMap2D*>(&grid), 0.7f, kParticles);
}

void BM_FilterStep_Global(benchmark::State& state) {
    auto& s = setup();
    mrpt::random::getRandomGenerator().randomize(1);
    simp::localization::ObjectMcl mcl(s.map, kParticles);
    auto pf = makeFilter();
    mrpt::bayes::CParticleFilter::TParticleFilterStats stats;
    for (auto _ : state) {
        state.PauseTiming();
        resetUniform(mcl, s.world.floorplan);
        state.ResumeTiming();
        pf.executeOn(mcl, &s.action, &s.frame, &stats);
        benchmark::DoNotOptimize(stats.ESS_beforeResample);
    }
    state.counters["particles"] = static_cast<double>(mcl.particlesCount());
    state.counters["K"] = static_cast<double>(kDetections);
}
BENCHMARK(BM_FilterStep_Global)->Unit(benchmark::kMillisecond);

void BM_FilterStep_Tracking(benchmark::State& state) {
    auto& s = setup();
    mrpt::random::getRandomGenerator().randomize(2);
    simp::localization::ObjectMcl mcl(s.map, kParticles);
    mcl.resetUniform(s.truth.x - 0.3, s.truth.x + 0.3, s.truth.y - 0.3, s.truth.y + 0.3, s.truth.phi - 0.2,
                     s.truth.phi + 0.2, kParticles);
    auto pf = makeFilter();
    for (auto _ : state) pf.executeOn(mcl, &s.action, &s.frame);
    state.counters["particles"] = static_cast<double>(mcl.particlesCount());
}
BENCHMARK(BM_FilterStep_Tracking)->Unit(benchmark::kMillisecond);

// What [ManhattanHeading] adds to a step: the K box yaws against the map's axes for every particle.
void BM_ManhattanHeading(benchmark::State& state) {
    auto& s = setup();
    mrpt::random::getRandomGenerator().randomize(3);
    simp::localization::ObjectMcl mcl(s.map, kParticles);
    resetUniform(mcl, s.world.floorplan);
    simp::localization::ManhattanHeadingOptions options;
    options.weight = 0.5;
    const simp::localization::ManhattanHeading model(*s.map, options);
    if (!model.active()) state.SkipWithError("the map has no axes");
    const auto observations = simp::localization::objectObservations(s.frame);
    for (auto _ : state) mcl.weighHeading(model, observations, 1.0);
    state.counters["particles"] = static_cast<double>(mcl.particlesCount());
}
BENCHMARK(BM_ManhattanHeading)->Unit(benchmark::kMicrosecond);

}  // namespace
