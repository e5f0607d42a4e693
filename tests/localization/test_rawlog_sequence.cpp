/// Reading rawlogs in both MRPT formats into frames with odometry increments.

#include "TestUtil.h"
#include "common/MrptTool.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/localization/RawlogSequence.h>
#include <simp/obs/CObservationObjects3D.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

using namespace simp::localization;

TEST(RawlogSequence, BothFormatsGiveTheSameFramesAndIncrements) {
    const auto& sc = test::sharedScenario();
    const auto af = loadRawlogSequence(sc.rawlog_path);
    const auto ob = loadRawlogSequence(sc.rawlog_obs_only_path);
    EXPECT_EQ(af.format, "actions+sensoryframes");
    EXPECT_EQ(ob.format, "observations");
    ASSERT_EQ(af.frames.size(), sc.groundtruth.size());
    ASSERT_EQ(ob.frames.size(), sc.groundtruth.size());
    mrpt::poses::CPose2D odo_af, odo_ob;
    for (std::size_t i = 0; i < af.frames.size(); ++i) {
        EXPECT_NEAR(af.frames[i].t_s, sc.groundtruth[i].t_s, 1e-6);
        EXPECT_NEAR(ob.frames[i].t_s, sc.groundtruth[i].t_s, 1e-6);
        EXPECT_EQ(af.frames[i].observations->size(), 4u);  // the 4 cameras
        EXPECT_EQ(ob.frames[i].observations->size(), 4u);
        odo_af = odo_af + af.frames[i].odometry_increment;
        odo_ob = odo_ob + ob.frames[i].odometry_increment;
        EXPECT_NEAR(af.frames[i].odometry_increment.x(), ob.frames[i].odometry_increment.x(), 1e-9);
        EXPECT_NEAR(af.frames[i].odometry_increment.phi(), ob.frames[i].odometry_increment.phi(), 1e-9);
    }
    // Integrated odometry ends near the true displacement (3 % noise): within 1.5 m after ~30 m... here
    // the path is ~24 m long.
    const auto gt_rel = mrpt::poses::CPose2D(sc.groundtruth.back().pose) - mrpt::poses::CPose2D(sc.groundtruth.front().pose);
    EXPECT_NEAR(odo_af.x(), gt_rel.x(), 1.5);
    EXPECT_NEAR(odo_af.y(), gt_rel.y(), 1.5);
}

TEST(RawlogSequence, ErrorsNameTheFile) {
    const std::string dir = test::freshOutputDir("rawlog_errors");
    std::filesystem::create_directories(dir);
    auto message = [](const std::string& path) {
        try {
            loadRawlogSequence(path);
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message(dir + "/absent.rawlog").find("absent.rawlog"), std::string::npos);
    std::ofstream(dir + "/garbage.rawlog") << "this is not a rawlog";
    const std::string g = message(dir + "/garbage.rawlog");
    EXPECT_NE(g.find("garbage.rawlog"), std::string::npos);
    EXPECT_NE(g.find("corrupt"), std::string::npos);
    std::ofstream(dir + "/empty.rawlog").close();
    const std::string e = message(dir + "/empty.rawlog");
    EXPECT_NE(e.find("empty.rawlog"), std::string::npos);
    EXPECT_NE(e.find("no sensory frame"), std::string::npos);
    {  // only objects the filter does not use
        mrpt::io::CFileGZOutputStream f(dir + "/comments.rawlog");
        mrpt::obs::CObservationComment c;
        c.text = "hello";
        c.timestamp = mrpt::Clock::fromDouble(5.0);
        mrpt::serialization::archiveFrom(f) << c;
    }
    EXPECT_EQ(loadRawlogSequence(dir + "/comments.rawlog").frames.size(), 1u);  // a frame without detections
}

namespace {

/// Runs MRPT's rawlog-edit with the plugin; returns its exit status (output in `log`).
int rawlogEdit(const std::string& args, std::string& log) {
    const std::string cmd = simp_test::mrptToolEnv() + "rawlog-edit -w --plugins " + std::string(SIMP_BINARY_DIR) +
                            "/lib/libsimp_obs.so " + args + " 2>&1";
    log.clear();
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return -1;
    char buf[4096];
    while (std::fgets(buf, sizeof buf, p)) log += buf;
    const int status = pclose(p);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST(RawlogSequence, TimeStampsGoingBackwardsAreRefusedNamingTheEntry) {
    if (std::system("command -v rawlog-edit > /dev/null") != 0)
        GTEST_SKIP() << "rawlog-edit (Debian package mrpt-apps) is not installed";
    const auto& sc = test::sharedScenario();
    const std::string dir = test::freshOutputDir("remapped_timestamps");
    std::filesystem::create_directories(dir);
    std::string log;

    // t -> t + 100: MRPT shifts the observations (not the actions); frames take their
    // observations' times, so the sequence is read, shifted, in order.
    const std::string shifted = dir + "/shifted.rawlog";
    ASSERT_EQ(rawlogEdit("--remap-timestamps \"1;100\" -i " + sc.rawlog_path + " -o " + shifted, log), 0) << log;
    const auto seq = loadRawlogSequence(shifted);
    ASSERT_EQ(seq.frames.size(), sc.groundtruth.size());
    for (std::size_t i = 0; i < seq.frames.size(); ++i)
        EXPECT_NEAR(seq.frames[i].t_s, sc.groundtruth[i].t_s + 100.0, 1e-5);

    // t -> -t: the frames' times go backwards: refused, naming the file, the entry and both times.
    const std::string reversed = dir + "/reversed.rawlog";
    ASSERT_EQ(rawlogEdit("--remap-timestamps \"-1;0\" -i " + sc.rawlog_path + " -o " + reversed, log), 0) << log;
    try {
        loadRawlogSequence(reversed);
        FAIL() << "a rawlog whose time goes backwards was accepted";
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("reversed.rawlog"), std::string::npos) << m;
        EXPECT_NE(m.find("entry 3 (frame 1)"), std::string::npos) << m;  // entries: action, frame, action, frame
        EXPECT_NE(m.find("is not after the previous frame's"), std::string::npos) << m;
        EXPECT_NE(m.find("(entry 1)"), std::string::npos) << m;
    }
}
