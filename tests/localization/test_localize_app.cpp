/// simp-localize end to end on a generated world and sequence (tests/localization/SyntheticScenario.h).

#include "TestUtil.h"

#include "common/ErrorOf.h"

#include <gtest/gtest.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <opencv2/imgcodecs.hpp>
#include <simp/eval/FigureColors.h>
#include <simp/eval/Scene3D.h>
#include <simp/io/Tum.h>
#include <simp/world/World.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace fs = std::filesystem;
using namespace simp::localization;
using namespace simp::localization::test;

namespace {

constexpr double kConvergedXY = 0.3;         // m, the paper's convergence criterion
constexpr double kConvergedPhi = M_PI / 4;   // rad

std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

std::size_t lineCount(const std::string& path) {
    std::ifstream f(path);
    std::size_t n = 0;
    for (std::string line; std::getline(f, line);)
        if (!line.empty() && line[0] != '#') ++n;
    return n;
}

bool converged(const StepRecord& s, const simp::io::StampedPose2D& gt) {
    return translationError(s.estimate, gt.pose) <= kConvergedXY && headingError(s.estimate, gt.pose) <= kConvergedPhi;
}

std::vector<std::string> baseArgs(const Scenario& sc, const std::string& out) {
    return {"--world", sc.world_dir, "--rawlog", sc.rawlog_path, "--out", out, "--config",
            std::string(SIMP_SOURCE_DIR) + "/config_ini/simp.ini", "--particles", "2000", "--seed", "3"};
}

/// Replaces the value of option `name` in `args` (appends it when absent).
void setArg(std::vector<std::string>& args, const std::string& name, const std::string& value) {
    for (std::size_t i = 0; i + 1 < args.size(); ++i)
        if (args[i] == name) {
            args[i + 1] = value;
            return;
        }
    args.insert(args.end(), {name, value});
}

using simp_test::errorOf;

}  // namespace

TEST(LocalizeApp, SimpConvergesGloballyAndStaysConverged) {
    const Scenario& sc = sharedScenario();
    const std::string out = freshOutputDir("simp");
    LocalizeApp app;
    runApp(app, baseArgs(sc, out));
    ASSERT_EQ(app.steps.size(), sc.groundtruth.size());
    EXPECT_EQ(app.sensor_model_used, "simp");

    // The final estimate: within the paper's convergence radius.
    const auto& last = app.steps.back();
    EXPECT_LE(translationError(last.estimate, sc.groundtruth.back().pose), kConvergedXY);
    EXPECT_LE(headingError(last.estimate, sc.groundtruth.back().pose), kConvergedPhi);

    // Converged before the end: the final converged streak starts in the first 60 % of the run
    // (the paper's success criterion asks for the first 95 %).
    std::size_t streak_start = app.steps.size();
    while (streak_start > 0 && converged(app.steps[streak_start - 1], sc.groundtruth[streak_start - 1]))
        --streak_start;
    ASSERT_LT(streak_start, app.steps.size());
    const double t_conv = sc.groundtruth[streak_start].t_s - sc.groundtruth.front().t_s;
    EXPECT_LE(t_conv, 0.6 * sc.duration_s) << "converged at " << t_conv << " s of " << sc.duration_s << " s";
    // After convergence the error is at the level of the detector noise (centre sigma 8 cm,
    // averaged over the frame's detections): RMSE well under the 0.3 m convergence radius.
    double sum2 = 0;
    for (std::size_t i = streak_start; i < app.steps.size(); ++i)
        sum2 += std::pow(translationError(app.steps[i].estimate, sc.groundtruth[i].pose), 2);
    EXPECT_LT(std::sqrt(sum2 / static_cast<double>(app.steps.size() - streak_start)), 0.15);
    // After the first update the particles are still spread over the floor plan, and the filter
    // does not claim a pose yet.
    EXPECT_GT(app.steps.front().cov(0, 0), 1.0);
    EXPECT_EQ(app.steps.front().state, LocalizationState::Global);

    // While it says localized, the pose is within the paper's bounds.
    std::size_t first_localized = app.steps.size(), localized = 0, localized_ok = 0;
    for (std::size_t i = 0; i < app.steps.size(); ++i) {
        if (app.steps[i].state != LocalizationState::Localized) continue;
        first_localized = std::min(first_localized, i);
        ++localized;
        localized_ok += converged(app.steps[i], sc.groundtruth[i]);
    }
    ASSERT_GT(localized, app.steps.size() / 2);
    EXPECT_EQ(localized_ok, localized);

    // Outputs: estimate.tum from the first localized step on, every frame after it (frame times);
    // steps.csv with a header and a row per frame, PNG, particles.
    const auto tum = simp::io::readTum(out + "/estimate.tum");
    ASSERT_EQ(tum.size(), sc.groundtruth.size() - first_localized);
    for (std::size_t i = 0; i < tum.size(); ++i)
        EXPECT_NEAR(tum[i].t_s, sc.groundtruth[first_localized + i].t_s, 1e-6);
    EXPECT_EQ(lineCount(out + "/steps.csv"), sc.groundtruth.size() + 1);
    EXPECT_EQ(slurp(out + "/steps.csv").substr(0, stepsCsvHeader().size()), stepsCsvHeader());
    {  // every row has the header's columns, with and without a challenger
        const std::string header = stepsCsvHeader();
        const auto commas = [](const std::string& t) { return std::count(t.begin(), t.end(), ','); };
        std::istringstream rows(slurp(out + "/steps.csv"));
        for (std::string row; std::getline(rows, row);) ASSERT_EQ(commas(row), commas(header)) << row;
        StepRecord with_challenger;
        with_challenger.challenger_particles = 10;
        EXPECT_EQ(commas(stepsCsvLine(with_challenger)), commas(header));
    }
    EXPECT_EQ(lineCount(out + "/final_particles.txt"), app.final_particles.size());
    EXPECT_GT(fs::file_size(out + "/trajectory.png"), 1000u);
    // A converged set is concentrated: its spread is well below the room size.
    EXPECT_LT(std::sqrt(last.cov(0, 0) + last.cov(1, 1)), 0.5);
}

TEST(LocalizeApp, GroundTruthAndThreeDSceneShowTheRun) {
    const Scenario& sc = sharedScenario();
    const std::string out = freshOutputDir("scene3d");
    auto args = baseArgs(sc, out);
    setArg(args, "--particles", "500");
    setArg(args, "--gt", sc.groundtruth_path);
    setArg(args, "--3dscene", out + "/run.3Dscene");
    LocalizeApp app;
    runApp(app, args);

    const auto scene = simp::eval::loadScene(out + "/run.3Dscene");
    EXPECT_TRUE(scene->getByName(simp::eval::scene_names::kFloorplan));
    const auto objects =
        std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(scene->getByName(simp::eval::scene_names::kObjects));
    ASSERT_TRUE(objects);
    EXPECT_EQ(objects->size(), 2 * simp::world::loadWorld(sc.world_dir).objects.objects.size());  // box + label each
    const auto lines = [&](const char* name) {
        const auto l = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(scene->getByName(name));
        return l ? l->getLineCount() + 1 : 0;
    };
    EXPECT_EQ(lines(simp::eval::scene_names::kGroundTruth), sc.groundtruth.size());
    EXPECT_EQ(lines(simp::eval::scene_names::kEstimate), app.estimate.size());
    const auto cloud =
        std::dynamic_pointer_cast<mrpt::opengl::CPointCloud>(scene->getByName(simp::eval::scene_names::kParticles));
    ASSERT_TRUE(cloud);
    EXPECT_EQ(cloud->size(), app.final_particles.size());

    // trajectory.png draws the ground truth (green of the figures, simp::eval::drawTrajectoryMap)
    const cv::Mat3b png = cv::imread(out + "/trajectory.png");
    ASSERT_FALSE(png.empty());
    const cv::Scalar gt_bgr = simp::eval::toBgr(simp::obs::figure_colors::kGroundTruth);
    const cv::Vec3b gt_colour(static_cast<uchar>(gt_bgr[0]), static_cast<uchar>(gt_bgr[1]), static_cast<uchar>(gt_bgr[2]));
    int green = 0;
    for (int r = 0; r < png.rows; ++r)
        for (int c = 0; c < png.cols; ++c) green += png(r, c) == gt_colour;
    EXPECT_GT(green, 200);

    setArg(args, "--gt", out + "/absent.tum");
    args.insert(args.begin(), "simp-localize");
    LocalizeApp refused;
    const std::string error = errorOf([&] { refused.initialize(args); });
    EXPECT_NE(error.find("--gt"), std::string::npos) << error;
    EXPECT_NE(error.find("absent.tum"), std::string::npos) << error;
}

TEST(LocalizeApp, BaselinesRunEndToEnd) {
    const Scenario& sc = sharedScenario();
    for (const std::string method : {"edt", "d", "o"}) {
        const std::string out = freshOutputDir("baseline_" + method);
        auto args = baseArgs(sc, out);
        args.insert(args.end(), {"--method", method});
        LocalizeApp app;
        runApp(app, args);
        EXPECT_EQ(app.sensor_model_used, method);
        // estimate.tum from the first localized step on (the baselines run with the same machinery).
        std::size_t first = 0;
        while (first < app.steps.size() && app.steps[first].state != LocalizationState::Localized) ++first;
        EXPECT_LT(first, app.steps.size()) << method << " never localized";
        EXPECT_EQ(simp::io::readTum(out + "/estimate.tum").size(), sc.groundtruth.size() - first) << method;
        EXPECT_EQ(lineCount(out + "/steps.csv"), sc.groundtruth.size() + 1) << method;
    }
}

TEST(LocalizeApp, TheBaselinesRunFromSimpIniWithMethod) {
    // One .ini for every method (issue #15): the baselines are simp.ini with --method, nothing else changed.
    const Scenario& sc = sharedScenario();
    LocalizeApp simp_app;
    simp_app.initialize(std::vector<std::string>{"simp-localize", "--world", sc.world_dir, "--rawlog", sc.rawlog_path,
                                                 "--out", freshOutputDir("ini_simp_only"), "--quiet", "--config",
                                                 std::string(SIMP_SOURCE_DIR) + "/config_ini/simp.ini"});
    for (const std::string method : {"simp", "edt", "d", "o"}) {
        const std::string out = freshOutputDir("ini_" + method);
        LocalizeApp app;
        app.initialize(std::vector<std::string>{"simp-localize", "--world", sc.world_dir, "--rawlog", sc.rawlog_path,
                                                "--out", out, "--quiet", "--config",
                                                std::string(SIMP_SOURCE_DIR) + "/config_ini/simp.ini", "--method", method});
        EXPECT_EQ(app.options.experiment.particles_count, 5000u) << method;  // the paper's particle count
        EXPECT_EQ(app.options.challenger.window, simp_app.options.challenger.window) << method;
        EXPECT_EQ(app.options.search.pair_candidates, simp_app.options.search.pair_candidates) << method;
        app.options.experiment.particles_count = 200;                        // keep the test fast
        app.run();
        EXPECT_EQ(app.sensor_model_used, method);
    }
}

TEST(LocalizeApp, SameSeedGivesIdenticalEstimate) {
    const Scenario& sc = sharedScenario();
    const std::string a = freshOutputDir("seed_a"), b = freshOutputDir("seed_b"), c = freshOutputDir("seed_c");
    auto args_a = baseArgs(sc, a), args_b = baseArgs(sc, b), args_c = baseArgs(sc, c);
    for (auto* args : {&args_a, &args_b, &args_c}) setArg(*args, "--particles", "500");
    setArg(args_c, "--seed", "4");
    LocalizeApp app_a, app_b, app_c;
    runApp(app_a, args_a);
    runApp(app_b, args_b);
    runApp(app_c, args_c);
    EXPECT_EQ(slurp(a + "/estimate.tum"), slurp(b + "/estimate.tum"));
    EXPECT_EQ(slurp(a + "/final_particles.txt"), slurp(b + "/final_particles.txt"));
    EXPECT_NE(slurp(a + "/final_particles.txt"), slurp(c + "/final_particles.txt"));
}

TEST(LocalizeApp, ObservationOnlyRawlogGivesTheSameFrames) {
    const Scenario& sc = sharedScenario();
    const std::string out = freshOutputDir("obs_only");
    auto args = baseArgs(sc, out);
    args[3] = sc.rawlog_obs_only_path;
    setArg(args, "--particles", "500");
    LocalizeApp app;
    runApp(app, args);
    ASSERT_EQ(app.steps.size(), sc.groundtruth.size());
    for (std::size_t i = 0; i < app.steps.size(); ++i) EXPECT_NEAR(app.steps[i].t_s, sc.groundtruth[i].t_s, 1e-6);
}

TEST(LocalizeApp, HelpDoesNothingAndSucceeds) {
    LocalizeApp app;
    testing::internal::CaptureStdout();
    app.initialize(std::vector<std::string>{"simp-localize", "--help"});
    const std::string text = testing::internal::GetCapturedStdout();
    EXPECT_TRUE(app.help_requested);
    EXPECT_NE(text.find("--rawlog"), std::string::npos);
    EXPECT_NO_THROW(app.run());
}

TEST(LocalizeApp, BadInputsNameTheFile) {
    const Scenario& sc = sharedScenario();
    const std::string out = freshOutputDir("errors");
    fs::create_directories(out);

    // Missing rawlog.
    auto args = baseArgs(sc, out);
    args[3] = out + "/nope.rawlog";
    EXPECT_NE(errorOf([&] { LocalizeApp app; runApp(app, args); }).find("nope.rawlog"), std::string::npos);

    // Truncated rawlog (still being written): a real one cut in the middle of an entry is localized
    // up to the last complete entry, with a warning.
    const std::string truncated = out + "/truncated.rawlog";
    const std::string all = slurp(sc.rawlog_path);
    {
        std::ofstream f(truncated, std::ios::binary);
        f.write(all.data(), static_cast<std::streamsize>(all.size() * 2 / 3));
    }
    args = baseArgs(sc, out + "/trunc_run");
    args[3] = truncated;
    setArg(args, "--particles", "200");
    {
        LocalizeApp app;
        std::ostringstream log;
        args.insert(args.begin(), "simp-localize");
        args.push_back("--quiet");
        app.initialize(args);
        app.log = &log;
        app.run();
        EXPECT_GT(app.truncated_at_entry, 0u);
        EXPECT_GT(app.steps.size(), sc.groundtruth.size() / 2);
        EXPECT_LT(app.steps.size(), sc.groundtruth.size());
        EXPECT_NE(log.str().find("incomplete entry"), std::string::npos) << log.str();
    }
    // Corrupt bytes in the middle are an error naming the file and the entry.
    const std::string corrupt = out + "/corrupt.rawlog";
    {
        std::string bytes = all;
        for (std::size_t i = bytes.size() / 3; i < bytes.size() / 3 + 64; ++i) bytes[i] = static_cast<char>(0xA5);
        std::ofstream(corrupt, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    args = baseArgs(sc, out);
    args[3] = corrupt;
    const std::string trunc_err = errorOf([&] { LocalizeApp app; runApp(app, args); });
    EXPECT_NE(trunc_err.find("corrupt.rawlog"), std::string::npos) << trunc_err;
    EXPECT_NE(trunc_err.find("entry"), std::string::npos) << trunc_err;

    // --initial-pose: malformed, or outside the free space.
    for (const std::string bad : {"1,2", "1,2,x", "1,2,3,4", "1,2,3,-1,0.1", "nan,2,3"}) {
        args = baseArgs(sc, out);
        args.insert(args.end(), {"--initial-pose", bad});
        const std::string e = errorOf([&] { LocalizeApp app; runApp(app, args); });
        EXPECT_NE(e.find("--initial-pose"), std::string::npos) << bad << ": " << e;
    }
    args = baseArgs(sc, out);
    args.insert(args.end(), {"--initial-pose", "-500,-500,0"});
    const std::string outside = errorOf([&] { LocalizeApp app; runApp(app, args); });
    EXPECT_NE(outside.find("free space"), std::string::npos) << outside;

    // Missing world directory, and a world directory without its files.
    args = baseArgs(sc, out);
    args[1] = out + "/no_world";
    EXPECT_NE(errorOf([&] { LocalizeApp app; runApp(app, args); }).find("no_world"), std::string::npos);
    fs::create_directories(out + "/empty_world");
    args[1] = out + "/empty_world";
    EXPECT_NE(errorOf([&] { LocalizeApp app; runApp(app, args); }).find("empty_world"), std::string::npos);

    // Unknown --method.
    args = baseArgs(sc, out);
    args.insert(args.end(), {"--method", "lidar"});
    EXPECT_NE(errorOf([&] { LocalizeApp app; runApp(app, args); }).find("lidar"), std::string::npos);

    // An .ini key the project does not know, and a bad value: both name the file and the key.
    const std::string bad_ini = out + "/bad.ini";
    std::ofstream(bad_ini) << "[LocalizationExperiment]\nparticle_count = 100\n";
    args = baseArgs(sc, out);
    args[7] = bad_ini;
    std::string err = errorOf([&] { LocalizeApp app; runApp(app, args); });
    EXPECT_NE(err.find("bad.ini"), std::string::npos) << err;
    EXPECT_NE(err.find("particle_count"), std::string::npos) << err;
    std::ofstream(bad_ini) << "[MotionModel]\na1 = fast\n";
    err = errorOf([&] { LocalizeApp app; runApp(app, args); });
    EXPECT_NE(err.find("bad.ini"), std::string::npos) << err;
    EXPECT_NE(err.find("a1"), std::string::npos) << err;

    // MRPT's own loader: a required [PF_options] key missing; a PF algorithm MRPT's MCL lacks.
    std::ofstream(bad_ini) << "[PF_options]\nPF_algorithm = pfStandardProposal\n";
    err = errorOf([&] { LocalizeApp app; runApp(app, args); });
    EXPECT_NE(err.find("bad.ini"), std::string::npos) << err;
    EXPECT_NE(describeError(std::runtime_error(err)).find("not found"), std::string::npos) << err;
    EXPECT_EQ(err.find("Call stack"), std::string::npos) << err;
    std::ofstream(bad_ini) << "[PF_options]\nPF_algorithm = pfOptimalProposal\nresamplingMethod = prSystematic\n"
                              "adaptiveSampleSize = false\nBETA = 0.5\nsampleSize = 1\n";
    err = errorOf([&] { LocalizeApp app; runApp(app, args); });
    EXPECT_NE(err.find("pfOptimalProposal"), std::string::npos) << err;

    // Missing .ini, missing required argument.
    args = baseArgs(sc, out);
    args[7] = out + "/missing.ini";
    EXPECT_NE(errorOf([&] { LocalizeApp app; runApp(app, args); }).find("missing.ini"), std::string::npos);
    EXPECT_NE(errorOf([&] { LocalizeApp app; runApp(app, {"--world", sc.world_dir}); }).find("--rawlog"),
              std::string::npos);
}
