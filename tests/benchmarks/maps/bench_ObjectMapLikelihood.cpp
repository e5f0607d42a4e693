// Sensor model throughput: CObjectMap::accumulateLogLikelihoods for 5000 particles and K
// detections, on the simp-office ground-truth map (doc/performance.md).
#include <benchmark/benchmark.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/world/SimpFormat.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <iostream>
#include <random>

namespace {

using mrpt::math::TPose2D;

constexpr std::size_t kParticles = 5000;

struct BenchMap {
    simp::world::ObjectMapData data;
    std::string source;
};

/// ~90 objects of 6 classes over 26 m x 14 m, for machines without the authors' data.
simp::world::ObjectMapData generatedMap(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ux(-13.0, 13.0), uy(-7.0, 7.0), uyaw(-M_PI, M_PI), usize(0.4, 1.6);
    simp::world::ObjectMapData m;
    m.class_names = simp::obs::defaultClassNames();
    m.class_noise.assign(m.class_names.size(), std::nullopt);
    const std::vector<std::string> classes = {"chair", "table", "desk", "cabinet", "door", "board"};
    for (const auto& c : classes) {
        simp::model::NoiseModel n;
        n.cov_m2 = Eigen::Vector2d(0.25 * 0.25, 0.15 * 0.15).asDiagonal();
        m.class_noise[m.classId(c)] = n;
    }
    for (int i = 0; i < 90; ++i) {
        simp::world::MapObject o;
        o.id = i;
        o.class_id = m.classId(classes[i % classes.size()]);
        o.box = simp::geometry::makeUprightBox({ux(rng), uy(rng), 0.5}, {usize(rng), usize(rng), 1.0}, uyaw(rng));
        m.objects.push_back(o);
    }
    return m;
}

const BenchMap& benchMap() {
    static const BenchMap map = [] {
        const std::string dir = std::string(SIMP_SHARED_DATA_DIR) + "/simp-office";
        BenchMap b;
        if (std::filesystem::exists(dir + "/global_variance.json")) {
            b.data = simp::world::importSimpMap(dir).objects;
            b.source = "simp-office (" + std::to_string(b.data.objects.size()) + " objects)";
        } else {
            b.data = generatedMap(1);
            b.source = "GENERATED map (" + std::to_string(b.data.objects.size()) + " objects; " + dir + " is absent)";
        }
        std::cout << "object map: " << b.source << "\n";
        return b;
    }();
    return map;
}

Eigen::Isometry3d isometry(const mrpt::poses::CPose3D& p) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = p.getRotationMatrix().asEigen();
    T.translation() = Eigen::Vector3d(p.x(), p.y(), p.z());
    return T;
}

/// K detections equal to the K map objects nearest to `truth` (camera 1 m high, forward).
simp::obs::CObservationObjects3D detections(const simp::world::ObjectMapData& m, const TPose2D& truth, std::size_t K) {
    simp::obs::CObservationObjects3D o;
    o.setCameraPose(simp::obs::cameraPoseOnRobot(0.1, 0.0, 1.0, 0.0));
    const Eigen::Isometry3d camera_T_world =
        (isometry(mrpt::poses::CPose3D(truth.x, truth.y, 0, truth.phi, 0, 0)) * isometry(o.cameraPose())).inverse();
    std::vector<std::size_t> order(m.objects.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    const Eigen::Vector2d t(truth.x, truth.y);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return (m.objects[a].box.center.head<2>() - t).norm() < (m.objects[b].box.center.head<2>() - t).norm();
    });
    std::vector<simp::obs::Detection3D> dets;
    for (std::size_t j = 0; j < K && j < order.size(); ++j) {
        const auto& obj = m.objects[order[j]];
        simp::obs::Detection3D d;
        d.class_id = static_cast<std::uint16_t>(
            simp::obs::classIndexOf(o.classNames(), m.class_names.at(static_cast<std::size_t>(obj.class_id))));
        d.confidence = 0.95f;
        d.box_in_camera = obj.box.transformed(camera_T_world);
        dets.push_back(d);
    }
    o.setDetections(dets);
    return o;
}

/// Particles: uniform over the objects' bounding box grown by 1 m (global localization), or
/// Gaussian around the truth with 0.3 m, 0.2 rad (tracking: most pairs hit an object).
std::vector<TPose2D> particles(const simp::world::ObjectMapData& m, const TPose2D& truth, bool global, unsigned seed) {
    std::mt19937 rng(seed);
    Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
    for (const auto& o : m.objects) {
        lo = lo.cwiseMin(o.box.center.head<2>());
        hi = hi.cwiseMax(o.box.center.head<2>());
    }
    std::uniform_real_distribution<double> ux(lo.x() - 1, hi.x() + 1), uy(lo.y() - 1, hi.y() + 1), uphi(-M_PI, M_PI);
    std::normal_distribution<double> n_xy(0.0, 0.3), n_phi(0.0, 0.2);
    std::vector<TPose2D> out(kParticles);
    for (auto& p : out)
        p = global ? TPose2D(ux(rng), uy(rng), uphi(rng))
                   : TPose2D(truth.x + n_xy(rng), truth.y + n_xy(rng), truth.phi + n_phi(rng));
    return out;
}

/// The likelihood options benchmarked: the defaults, without the yaw term, or the paper's model.
enum class Variant { Defaults, NoYaw, Paper };

/// NoYaw: the paper's Eq. combined (yaw_sigma_rad = 0), to see what the default yaw term costs.
/// Paper: also the noise models as the authors fitted them (mp_centre_noise_floor = 0) and no range
/// growth: wider supports, so that nearly every tracking pair needs the clipping (issue #13's case).
void run(benchmark::State& state, simp::maps::SensorModelType type, bool global, Variant variant = Variant::Defaults) {
    const auto& bm = benchMap();
    simp::maps::CObjectMap map;
    map.likelihoodOptions.sensor_model = type;
    if (variant != Variant::Defaults) map.likelihoodOptions.yaw_sigma_rad = 0.0;
    if (variant == Variant::Paper) {
        map.likelihoodOptions.mp_centre_noise_floor = 0.0;
        map.likelihoodOptions.noise_reference_range_m = 0.0;
    }
    map.setData(bm.data);
    // The truth: near the middle object of the map, so the K nearest objects are around it.
    const auto& mid = bm.data.objects[bm.data.objects.size() / 2].box.center;
    const TPose2D truth(mid.x() - 1.5, mid.y(), 0.0);
    const auto K = static_cast<std::size_t>(state.range(0));
    const auto obs = detections(bm.data, truth, K);
    const auto poses = particles(bm.data, truth, global, 42);
    std::vector<double> sums(poses.size(), 0.0);
    std::size_t used = 0;
    for (auto _ : state) {
        used = 0;
        map.accumulateLogLikelihoods(obs, poses.data(), poses.size(), sums.data(), used);
        benchmark::DoNotOptimize(sums.data());
        benchmark::ClobberMemory();
    }
    const double pairs = static_cast<double>(poses.size() * used);
    // Where the time goes: fraction of pairs whose centre falls in an m_p support (p_o > 0),
    // and fraction that also needs the polygon clipping (bounding circles overlap).
    if (type == simp::maps::SensorModelType::Simp) {
        const auto selected = map.sensorModel();
        const auto* model = std::get_if<simp::maps::SimpSensorModel>(&selected->model());
        std::size_t hits = 0, clips = 0, det_rects = 0;
        for (std::size_t k = 0; k < obs.size(); ++k) {
            const auto& det = obs.detections()[k];
            const int cls = bm.data.classId(obs.classNameOf(det));
            const auto prepared = model->prepare(cls, obs.boxInRobot(k), obs.footprintInRobot(k));
            if (!prepared) continue;
            det_rects += prepared->is_rect ? 1 : 0;
            for (const auto& p : poses) {
                const double c = std::cos(p.phi), s = std::sin(p.phi);
                const Eigen::Vector2d w(c * prepared->center_robot_m.x() - s * prepared->center_robot_m.y() + p.x,
                                        s * prepared->center_robot_m.x() + c * prepared->center_robot_m.y() + p.y);
                const auto hit = model->probabilityMap().lookup(cls, w.x(), w.y());
                if (hit.object < 0) continue;
                ++hits;
                const auto& of = model->footprints().objects[static_cast<std::size_t>(hit.object)];
                if (simp::maps::circlesOverlap(w, prepared->radius_m, of.circle_center_m, of.circle_radius_m)) ++clips;
            }
        }
        // Rectangular footprints take the fast IoU path (geometry/OrientedRect.h).
        std::size_t rects = 0;
        for (const auto& f : model->footprints().objects) rects += f.is_rect ? 1 : 0;
        state.counters["rect_frac"] = static_cast<double>(rects) / static_cast<double>(model->footprints().objects.size());
        state.counters["hit_frac"] = static_cast<double>(hits) / pairs;
        state.counters["clip_frac"] = static_cast<double>(clips) / pairs;
        state.counters["det_rect_frac"] = static_cast<double>(det_rects) / static_cast<double>(used);
    }
    // Seconds per (particle x detection): printed with an SI prefix, e.g. "40n" = 40 ns.
    state.counters["time_per_pair"] =
        benchmark::Counter(pairs, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["pairs"] = pairs;
    state.SetLabel(bm.source);
}

void BM_Simp_Global(benchmark::State& s) { run(s, simp::maps::SensorModelType::Simp, true); }
void BM_Simp_Tracking(benchmark::State& s) { run(s, simp::maps::SensorModelType::Simp, false); }
void BM_Simp_Tracking_NoYaw(benchmark::State& s) { run(s, simp::maps::SensorModelType::Simp, false, Variant::NoYaw); }
void BM_Simp_Tracking_Paper(benchmark::State& s) { run(s, simp::maps::SensorModelType::Simp, false, Variant::Paper); }
void BM_D_Global(benchmark::State& s) { run(s, simp::maps::SensorModelType::D, true); }
void BM_O_Global(benchmark::State& s) { run(s, simp::maps::SensorModelType::O, true); }
void BM_Edt_Global(benchmark::State& s) { run(s, simp::maps::SensorModelType::Edt, true); }

BENCHMARK(BM_Simp_Global)->Arg(1)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Simp_Tracking)->Arg(1)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Simp_Tracking_NoYaw)->Arg(1)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Simp_Tracking_Paper)->Arg(1)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_D_Global)->Arg(4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_O_Global)->Arg(4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Edt_Global)->Arg(4)->Unit(benchmark::kMicrosecond);

}  // namespace
