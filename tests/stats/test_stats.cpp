/// Tests of the statistical analysis (paper Sec. "Statistical Analysis"): matching rules, the
/// Gaussian fit and its standard errors, and simp-stats end to end on simulated detections whose
/// centres are drawn from a known per-class Gaussian in the object frame.
#include "common/ErrorOf.h"
#include <gtest/gtest.h>
#include <simp/model/NoiseFrame.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/detector_io/DetectionRawlog.h>
#include <simp/stats/GroundTruthMatch.h>
#include <simp/stats/NoiseFit.h>
#include <simp/stats/StatsApp.h>
#include <simp/world/ObjectMapData.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;
using namespace simp;

namespace {

std::string outDir(const std::string& name) {
    const fs::path p = fs::path(SIMP_TEST_OUTPUT_DIR) / "stats" / name;
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

world::MapObject object(int id, int cls, double x, double y, double yaw) {
    world::MapObject o;
    o.id = id;
    o.class_id = cls;
    o.box = geometry::makeUprightBox({x, y, 0.4}, {0.8, 0.5, 0.8}, yaw);
    return o;
}

/// The true noise of one class: offsets e = mu + L z, z ~ N(0, I), Sigma = L L^T.
struct TrueNoise {
    Eigen::Vector2d mu;
    Eigen::Matrix2d Sigma;
};

Eigen::Matrix2d covOf(double sx, double sy, double rho) {
    Eigen::Matrix2d S;
    S << sx * sx, rho * sx * sy, rho * sx * sy, sy * sy;
    return S;
}

/// A world of 3 chairs and 3 tables 4 m apart, with several yaws.
world::ObjectMapData makeWorld() {
    world::ObjectMapData w;
    w.class_names = {"chair", "table"};
    w.class_noise.assign(2, std::nullopt);
    int id = 1;
    for (int i = 0; i < 3; ++i) {
        w.objects.push_back(object(id++, 0, 4.0 * i, 0.0, 0.7 * i - 0.5));
        w.objects.push_back(object(id++, 1, 4.0 * i, 4.0, 2.1 - 1.3 * i));
    }
    return w;
}

/// Writes Q/sequence.rawlog and Q/groundtruth.tum: `frames` frames 1 s apart at random robot
/// poses, each with one camera observing every object once, centre drawn from the class noise.
void simulate(const std::string& dir, const world::ObjectMapData& w, const std::vector<TrueNoise>& noise,
              std::size_t frames, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    std::vector<io::StampedPose2D> poses;
    std::vector<obs::RawlogFrame> out;
    const mrpt::poses::CPose3D robot_T_camera = obs::cameraPoseOnRobot(0.1, 0.0, 0.63, 0.3);
    for (std::size_t k = 0; k < frames; ++k) {
        const double t = 1000.0 + static_cast<double>(k);
        const mrpt::math::TPose2D p(4.0 + u(rng), 2.0 + u(rng), u(rng));
        poses.push_back({t, p});
        const mrpt::poses::CPose3D world_T_camera = mrpt::poses::CPose3D(mrpt::poses::CPose2D(p)) + robot_T_camera;
        Eigen::Isometry3d camera_T_world = Eigen::Isometry3d::Identity();
        const auto inv = (-world_T_camera);
        camera_T_world.linear() = inv.getRotationMatrix().asEigen();
        camera_T_world.translation() = Eigen::Vector3d(inv.x(), inv.y(), inv.z());
        auto o = obs::CObservationObjects3D::Create();
        o->sensorLabel = "CAMERA_0";
        o->timestamp = mrpt::Clock::fromDouble(t);
        o->setCameraPose(robot_T_camera);
        o->setClassNames(w.class_names);
        for (const world::MapObject& m : w.objects) {
            const TrueNoise& n = noise[static_cast<std::size_t>(m.class_id)];
            const Eigen::Vector2d e = n.mu + n.Sigma.llt().matrixL() * Eigen::Vector2d(g(rng), g(rng));
            // in the class noise frame, where the simulator, the sensor model and the mapper read it
            const double yaw = model::classNoiseFrameYaw(m.box);
            geometry::Box3D b = m.box;
            b.center.head<2>() += Eigen::Rotation2Dd(yaw) * e;
            obs::Detection3D d;
            d.class_id = static_cast<std::uint16_t>(m.class_id);
            d.confidence = 0.9f;
            d.box_in_camera = b.transformed(camera_T_world);
            o->addDetection(d);
        }
        obs::RawlogFrame f;
        f.timestamp = o->timestamp;
        f.observations.push_back(o);
        out.push_back(f);
    }
    io::writeTum(dir + "/groundtruth.tum", poses);
    detector_io::writeDetectionRawlog(dir + "/sequence.rawlog", out);
}

using simp_test::errorOf;

}  // namespace

TEST(GroundTruthMatch, HighestIoUThenNearestThenDiscard) {
    world::ObjectMapData w;
    w.class_names = {"chair", "table"};
    w.objects = {object(1, 0, 0.0, 0.0, 0.0), object(2, 0, 0.6, 0.0, 0.0), object(3, 1, 0.1, 0.0, 0.0),
                 object(4, 0, 3.0, 0.0, 0.0)};
    // Prediction at x = 0.4: both chairs within delta and overlapping; object 2 overlaps more.
    geometry::Box3D p = geometry::makeUprightBox({0.4, 0.0, 0.4}, {0.8, 0.5, 0.8}, 0.0);
    auto m = stats::matchToGroundTruth(p, 0, w, 1.0);
    ASSERT_TRUE(m);
    EXPECT_EQ(w.objects[m->object_index].id, 2);
    EXPECT_GT(m->iou, 0.5);
    // No overlap with any chair (x = 2.0; nearest chair object 4 at 1.0 m... outside delta 0.9 -> none
    // of 2 (1.4 m)); with delta 1.5 both 2 and 4 are candidates, none overlaps: nearest centre = 4.
    p.center.x() = 2.0;
    EXPECT_FALSE(stats::matchToGroundTruth(p, 0, w, 0.9));
    m = stats::matchToGroundTruth(p, 0, w, 1.5);
    ASSERT_TRUE(m);
    EXPECT_EQ(w.objects[m->object_index].id, 4);
    EXPECT_DOUBLE_EQ(m->iou, 0.0);
    // Classes never mix: the table (object 3) is not a candidate for a chair.
    p.center.x() = 0.1;
    EXPECT_NE(w.objects[stats::matchToGroundTruth(p, 0, w, 1.0)->object_index].id, 3);
    EXPECT_THROW(stats::matchToGroundTruth(p, 0, w, 0.0), std::invalid_argument);
}

TEST(NoiseFit, RecoversGaussianWithinStandardErrors) {
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g(0.0, 1.0);
    const Eigen::Vector2d mu(0.07, -0.12);
    const Eigen::Matrix2d S = covOf(0.1, 0.2, 0.4);
    const Eigen::Matrix2d L = S.llt().matrixL();
    std::vector<Eigen::Vector2d> x;
    for (int i = 0; i < 4000; ++i) x.push_back(mu + L * Eigen::Vector2d(g(rng), g(rng)));
    for (const double r : {0.0, 3.0}) {  // plain ML and robust (truncated, corrected)
        const auto f = stats::fitGaussian(x, r);
        for (int i = 0; i < 2; ++i) EXPECT_NEAR(f.model.mean_m(i), mu(i), 4 * f.se_mean_m(i)) << "r=" << r;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) EXPECT_NEAR(f.model.cov_m2(i, j), S(i, j), 4 * f.se_cov_m2(i, j)) << "r=" << r;
    }
    // The histogram fit (5 cm cells + Sheppard's correction) agrees as well.
    const auto h = stats::makeHistogram(x, 0.05, mu, 1.0);
    EXPECT_EQ(h.outside, 0u);
    EXPECT_DOUBLE_EQ(h.counts.sum(), 4000.0);
    const auto fh = stats::fitGaussianFromHistogram(h);
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(fh.model.mean_m(i), mu(i), 4 * fh.se_mean_m(i));
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) EXPECT_NEAR(fh.model.cov_m2(i, j), S(i, j), 4 * fh.se_cov_m2(i, j));
    // Robust fit with 5 % gross outliers stays within the standard errors, the plain one does not.
    std::uniform_real_distribution<double> far(1.5, 2.0);
    for (int i = 0; i < 200; ++i) x.push_back(Eigen::Vector2d(far(rng), far(rng)));
    const auto plain = stats::fitGaussian(x, 0.0), robust = stats::fitGaussian(x, 3.0);
    EXPECT_GT(std::abs(plain.model.mean_m.x() - mu.x()), 10 * plain.se_mean_m.x());
    EXPECT_NEAR(robust.model.mean_m.x(), mu.x(), 4 * robust.se_mean_m.x());
    EXPECT_NEAR(robust.model.cov_m2(0, 0), S(0, 0), 4 * robust.se_cov_m2(0, 0));
    EXPECT_GE(robust.rejected, 200u);
    EXPECT_THROW(stats::fitGaussian({Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)}), std::invalid_argument);
    EXPECT_THROW(stats::fitGaussian({Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), Eigen::Vector2d(2, 2)}),
                 std::invalid_argument);  // collinear: singular
}

TEST(StatsApp, RecoversKnownPerClassNoise) {
    const std::string q = outDir("sim");
    const world::ObjectMapData w = makeWorld();
    world::saveObjectMap(w, q + "/objects.json");
    const std::vector<TrueNoise> truth = {{Eigen::Vector2d(0.05, -0.10), covOf(0.10, 0.18, 0.3)},
                                          {Eigen::Vector2d(-0.12, 0.04), covOf(0.15, 0.08, -0.4)}};
    simulate(q, w, truth, 500, 42);  // 1500 samples per class

    stats::StatsApp app;
    const std::string out = q + "/out";
    const std::vector<std::string> args = {"simp-stats", "--rawlog", q + "/sequence.rawlog", "--poses",
                                           q + "/groundtruth.tum", "--world", q + "/objects.json", "--out", out,
                                           "--delta", "1.0"};
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    std::ostringstream log;
    ASSERT_TRUE(app.initialize(static_cast<int>(argv.size()), argv.data(), log));
    ASSERT_EQ(app.run(log), 0);
    EXPECT_EQ(app.samples.counts.matched, 3000u) << log.str();
    for (std::size_t c = 0; c < 2; ++c) {
        ASSERT_TRUE(app.fits[c]) << app.class_names[c];
        const stats::NoiseFit& f = *app.fits[c];
        EXPECT_EQ(f.n, 1500u);
        for (int i = 0; i < 2; ++i) EXPECT_NEAR(f.model.mean_m(i), truth[c].mu(i), 4 * f.se_mean_m(i)) << c;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
                EXPECT_NEAR(f.model.cov_m2(i, j), truth[c].Sigma(i, j), 4 * f.se_cov_m2(i, j)) << c << i << j;
    }
    // class_noise.json is an object map file: the world's reader accepts it as it is.
    const auto back = world::loadObjectMap(out + "/class_noise.json");
    ASSERT_EQ(back.class_noise.size(), 2u);
    ASSERT_TRUE(back.class_noise[1]);
    EXPECT_DOUBLE_EQ(back.class_noise[1]->cov_m2(0, 1), app.fits[1]->model.cov_m2(0, 1));
    // class_noise.csv in the authors' units: 0.05 m cells, sx = sqrt(Sigma_xx) / 0.05.
    std::ifstream csv(out + "/class_noise.csv");
    std::string header, row0;
    std::getline(csv, header);
    std::getline(csv, row0);
    EXPECT_EQ(header, "category,mx,my,sx,sy,b");
    std::vector<double> v;
    std::stringstream ss(row0);
    for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 6u);
    EXPECT_NEAR(v[1], app.fits[0]->model.mean_m.x() / 0.05, 1e-9);
    EXPECT_NEAR(v[3], std::sqrt(app.fits[0]->model.cov_m2(0, 0)) / 0.05, 1e-9);
    EXPECT_TRUE(fs::exists(out + "/noise_chair.png"));
    EXPECT_TRUE(fs::exists(out + "/noise_table.png"));
}

TEST(StatsApp, BadInputIsNamed) {
    const auto init = [](std::vector<std::string> args) {
        args.insert(args.begin(), "simp-stats");
        std::vector<const char*> argv;
        for (const auto& a : args) argv.push_back(a.c_str());
        stats::StatsApp app;
        std::ostringstream log;
        app.initialize(static_cast<int>(argv.size()), argv.data(), log);
        app.run(log);
    };
    EXPECT_NE(errorOf([&] { init({"--rawlog", "a", "--poses", "b", "--world", "c"}); }).find("--out"), std::string::npos);
    EXPECT_NE(errorOf([&] { init({"--rawlog", "a", "--poses", "b", "--world", "c", "--out", "d", "--delta", "x"}); })
                  .find("--delta"),
              std::string::npos);
    const std::string d = outDir("bad");
    std::ofstream(d + "/bad.ini") << "[simp-stats]\ncell_size_m = -1\n";
    EXPECT_NE(errorOf([&] { init({"--rawlog", "a", "--poses", "b", "--world", "c", "--out", "d", "--config", d + "/bad.ini"}); })
                  .find("cell_size_m"),
              std::string::npos);
    world::ObjectMapData w = makeWorld();
    world::saveObjectMap(w, d + "/objects.json");
    EXPECT_NE(errorOf([&] { init({"--rawlog", d + "/missing.rawlog", "--poses", d + "/missing.tum", "--world",
                                  d + "/objects.json", "--out", d + "/o"}); })
                  .find("missing.tum"),
              std::string::npos);
    w.objects.clear();
    world::saveObjectMap(w, d + "/empty.json");
    EXPECT_NE(errorOf([&] { init({"--rawlog", "r", "--poses", "p", "--world", d + "/empty.json", "--out", d + "/o"}); })
                  .find("no objects"),
              std::string::npos);
}

TEST(StatsOptions, ExampleIniHoldsTheDefaults) {
    mrpt::config::CConfigFile cfg(std::string(SIMP_SOURCE_DIR) + "/tests/data/detector_io/simp-stats.ini");
    stats::StatsOptions o;
    o.delta_m = 7.0;
    o.fit_source = "histogram";
    o.loadFromConfigFile(cfg, "simp-stats");
    const stats::StatsOptions defaults;
    EXPECT_DOUBLE_EQ(o.delta_m, defaults.delta_m);
    EXPECT_EQ(o.fit_source, defaults.fit_source);
    EXPECT_DOUBLE_EQ(o.cell_size_m, 0.05);
    EXPECT_EQ(o.min_samples, defaults.min_samples);
}

TEST(StatsOptions, DocumentationAndExampleFollowTheDeclaration) {
    // doc/statistics.md's key table is StatsOptions::table().markdown() verbatim
    std::ifstream doc(std::string(SIMP_SOURCE_DIR) + "/doc/statistics.md");
    const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
    const std::string table = stats::StatsOptions::table().markdown(stats::StatsOptions{});
    EXPECT_NE(text.find(table), std::string::npos) << "doc/statistics.md should hold:\n" << table;
    // the example .ini sets every declared key, and nothing else
    mrpt::config::CConfigFile cfg(std::string(SIMP_SOURCE_DIR) + "/tests/data/detector_io/simp-stats.ini");
    std::vector<std::string> keys;
    cfg.getAllKeys("simp-stats", keys);
    std::sort(keys.begin(), keys.end());
    std::vector<std::string> declared = stats::StatsOptions::table().keys();
    std::sort(declared.begin(), declared.end());
    EXPECT_EQ(keys, declared);
    // the dump of what is used reads back to the same options
    stats::StatsOptions o;
    o.delta_m = 0.75, o.min_samples = 5, o.fit_source = "histogram";
    std::ostringstream dump;
    o.dumpToTextStream(dump);
    mrpt::config::CConfigFileMemory back(dump.str());
    stats::StatsOptions r;
    r.loadFromConfigFile(back, "simp-stats");
    EXPECT_DOUBLE_EQ(r.delta_m, 0.75);
    EXPECT_EQ(r.min_samples, 5);
    EXPECT_EQ(r.fit_source, "histogram");
}
