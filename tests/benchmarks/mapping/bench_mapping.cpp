// Speed of the object map builder: one time step of the 4-camera rig with ~100 map objects
// (the budget of doc/mapping.md: <= 10 ms on one core).
#include <benchmark/benchmark.h>
#include <simp/mapping/ObjectMapBuilder.h>

#include <random>

namespace {

using simp::geometry::makeUprightBox;

/// 26 m x 14 m floor (the authors' office size) with boundary walls and an inner wall at
/// x = 13 m with a 1 m door.
mrpt::maps::COccupancyGridMap2D officeFloor() {
    mrpt::maps::COccupancyGridMap2D g(-0.5f, 26.5f, -0.5f, 14.5f, 0.05f);
    const int x0 = g.x2idx(0.0), x1 = g.x2idx(26.0), y0 = g.y2idx(0.0), y1 = g.y2idx(14.0), wx = g.x2idx(13.0);
    for (int cy = 0; cy < static_cast<int>(g.getSizeY()); ++cy)
        for (int cx = 0; cx < static_cast<int>(g.getSizeX()); ++cx) {
            const double y = g.idx2y(cy);
            const bool outside = cx < x0 || cy < y0 || cx > x1 || cy > y1;
            const bool wall = cx == x0 || cy == y0 || cx == x1 || cy == y1 || (cx == wx && !(y > 6.5 && y < 7.5));
            g.setCell(cx, cy, outside ? 0.5f : wall ? 0.0f : 1.0f);
        }
    return g;
}

struct Scene {
    simp::mapping::ObjectMapBuilder builder;
    std::vector<mrpt::poses::CPose3D> poses;                             // two robot poses 0.25 m apart
    std::vector<std::vector<simp::obs::CObservationObjects3D>> frames;  // per pose: the 4 cameras
};

Scene makeScene(std::size_t n_objects) {
    simp::mapping::MappingOptions opts;
    opts.per_class.clear();
    opts.default_filter = simp::mapping::ClassFilter{0.5, 0.0, 5.0};
    Scene s{simp::mapping::ObjectMapBuilder(opts), {}, {}};
    const std::vector<std::string> classes = {"table", "cabinet", "chair", "sofa", "desk"};
    simp::world::ObjectMapData m;
    m.class_names = classes;
    m.class_noise.resize(classes.size());
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> ux(0.5, 25.5), uy(0.5, 13.5), uyaw(-M_PI, M_PI), usz(0.4, 1.4);
    for (std::size_t i = 0; i < n_objects; ++i) {
        simp::world::MapObject o;
        o.id = static_cast<std::int64_t>(i + 1);
        o.class_id = static_cast<int>(i % classes.size());
        const double h = usz(rng);
        o.box = makeUprightBox({ux(rng), uy(rng), 0.5 * h}, {usz(rng), usz(rng), h}, uyaw(rng));
        o.n_match = 10;
        m.objects.push_back(o);
    }
    s.builder.setFloorPlan(officeFloor(), {});
    s.builder.setMap(m);
    // Detections: the map objects near the robot at (6, 7), seen by the camera facing them.
    mrpt::img::TCamera K;
    K.ncols = 640, K.nrows = 480;
    K.setIntrinsicParamsFromValues(380.07, 379.66, 324.47, 237.79);
    for (const double x : {6.0, 6.25}) {
        const mrpt::poses::CPose3D robot(x, 7.0, 0, 0, 0, 0);
        s.poses.push_back(robot);
        s.frames.emplace_back();
        for (int c = 0; c < 4; ++c) {
            simp::obs::CObservationObjects3D o;
            o.setClassNames(classes);
            o.setCameraPose(simp::obs::cameraPoseOnRobot(0.1, 0, 0.63, -c * M_PI / 2));
            o.setIntrinsics(K);
            const mrpt::poses::CPose3D w = robot + o.cameraPose();
            Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
            T.linear() = w.getRotationMatrix().asEigen();
            T.translation() = Eigen::Vector3d(w.x(), w.y(), w.z());
            for (const auto& mo : m.objects) {
                const auto bc = mo.box.transformed(T.inverse());
                if (bc.center.z() < 0.5 || bc.center.norm() > 5.0 || std::abs(bc.center.x() / bc.center.z()) > 0.8)
                    continue;
                simp::obs::Detection3D d;
                d.class_id = static_cast<std::uint16_t>(mo.class_id);
                d.confidence = 0.9f;
                d.box_in_camera = bc;
                o.addDetection(d);
            }
            s.frames.back().push_back(o);
        }
    }
    return s;
}

/// One time step (4 camera frames) with an integration of the local map at every step (worst case:
/// the robot moves more than trigger_dist_m between steps).
void BM_MappingFrame4Cameras(benchmark::State& state) {
    Scene s = makeScene(static_cast<std::size_t>(state.range(0)));
    std::size_t step = 0;
    std::size_t detections = 0;
    for (const auto& o : s.frames[0]) detections += o.size();
    for (auto _ : state) {
        const std::size_t k = step++ % 2;
        for (const auto& o : s.frames[k]) s.builder.insert(o, s.poses[k]);
        benchmark::DoNotOptimize(s.builder.map().objects.size());
    }
    state.counters["map_objects"] = static_cast<double>(s.builder.map().objects.size());
    state.counters["detections"] = static_cast<double>(detections);
}
BENCHMARK(BM_MappingFrame4Cameras)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
