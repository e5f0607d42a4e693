// The kidnapped robot (simp-sim sequence --kidnap-at): one teleport that groundtruth.tum shows and
// odometry does not; its draws come from a stream of their own, so the sequence up to the
// teleport, and every file of a sequence without one, are what they were before.
#include <gtest/gtest.h>
#include <mrpt/io/CFileInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <nlohmann/json.hpp>
#include <simp/io/Tum.h>
#include <simp/obs/registerAllClasses.h>
#include <simp/sim/Office.h>
#include <simp/sim/Sequence.h>
#include <simp/sim/Trajectory.h>

#include "SimTestUtil.h"

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

using simp::sim::test::slurp;

simp::world::World smallOffice() {
    simp::sim::OfficeParams p;
    p.rooms = 4;
    return simp::sim::generateOffice(p, 21);
}

simp::sim::SimParams shortRun() {
    simp::sim::SimParams p;
    p.duration_s = 20;
    p.progress = false;
    return p;
}

/// The odometry increments (rawOdometryIncrementReading) of a rawlog, one per step; with
/// `bytes_after` the file position after each step (actions + sensory frame).
std::vector<mrpt::poses::CPose2D> readOdometry(const std::string& rawlog, std::vector<std::uint64_t>* bytes_after = nullptr) {
    simp::obs::registerAllClasses();
    mrpt::io::CFileInputStream f(rawlog);
    auto arch = mrpt::serialization::archiveFrom(f);
    std::vector<mrpt::poses::CPose2D> out;
    for (;;) {
        mrpt::serialization::CSerializable::Ptr o;
        try {
            o = arch.ReadObject();
        } catch (const std::exception&) {
            break;  // end of file
        }
        arch.ReadObject();  // the sensory frame
        auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(o);
        if (!acts || !acts->getBestMovementEstimation()) throw std::runtime_error("step without odometry");
        out.push_back(acts->getBestMovementEstimation()->rawOdometryIncrementReading);
        if (bytes_after) bytes_after->push_back(f.getPosition());
    }
    return out;
}

double planarDistance(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) { return std::hypot(b.x - a.x, b.y - a.y); }

TEST(SimKidnap, GroundTruthJumpsWhileOdometryShowsOrdinaryMotion) {
    const auto w = smallOffice();
    auto p = shortRun();
    p.kidnap_at_s = 10.0;
    p.odometry.noise_scale = 0;  // exact increments: the teleport's step must read exactly zero
    const std::string dir = simp::sim::test::clearedDir("kidnap_jump");
    const auto s = simp::sim::simulateSequence(w, p, 5, dir);
    ASSERT_TRUE(s.kidnap.has_value());
    EXPECT_EQ(s.kidnap->step, 100u);  // 10 s at 10 Hz
    EXPECT_DOUBLE_EQ(s.kidnap->t_s, p.epoch_s + 10.0);
    EXPECT_DOUBLE_EQ(s.kidnap->t_from_start_s, 10.0);

    const auto gt = simp::io::readTum(dir + "/groundtruth.tum");
    ASSERT_EQ(gt.size(), 201u);
    const double max_step_m = p.trajectory.speed_max_mps / p.odometry.rate_hz + 1e-5;  // TUM keeps 6 decimals
    for (std::size_t k = 1; k < gt.size(); ++k) {
        const double d = planarDistance(gt[k - 1].pose, gt[k].pose);
        if (k == 100) EXPECT_GE(d, p.kidnap_min_distance_m - 1e-5) << "the teleport is missing from groundtruth.tum";
        else EXPECT_LE(d, max_step_m) << "step " << k << " jumps";
    }
    EXPECT_NEAR(gt[99].pose.x, s.kidnap->from.x, 1e-6);
    EXPECT_NEAR(gt[99].pose.y, s.kidnap->from.y, 1e-6);
    EXPECT_NEAR(gt[100].pose.x, s.kidnap->to.x, 1e-6);
    EXPECT_NEAR(gt[100].pose.y, s.kidnap->to.y, 1e-6);
    EXPECT_NEAR(gt[100].t_s, s.kidnap->t_s, 1e-6);

    // the odometry: ordinary motion everywhere, nothing at the teleport; composed from the pose
    // it was put down at, it follows the ground truth again
    const auto odo = readOdometry(dir + "/sequence.rawlog");
    ASSERT_EQ(odo.size(), 200u);
    mrpt::poses::CPose2D pose(gt[0].pose);
    for (std::size_t k = 1; k <= odo.size(); ++k) {
        const auto& inc = odo[k - 1];
        EXPECT_LE(std::hypot(inc.x(), inc.y()), max_step_m) << "odometry of step " << k;
        if (k == 100) {
            EXPECT_EQ(inc.x(), 0.0);
            EXPECT_EQ(inc.y(), 0.0);
            EXPECT_EQ(inc.phi(), 0.0);
            pose = mrpt::poses::CPose2D(gt[100].pose);  // what a localizer has to find out
            continue;
        }
        pose = pose + inc;
        EXPECT_NEAR(pose.x(), gt[k].pose.x, 1e-5) << "step " << k;
        EXPECT_NEAR(pose.y(), gt[k].pose.y, 1e-5) << "step " << k;
    }
    // after the teleport the robot plans from its new pose and drives on
    EXPECT_GT(planarDistance(gt[100].pose, gt[200].pose), 0.5);

    // Q/kidnap.json
    std::ifstream f(dir + "/kidnap.json");
    const auto j = nlohmann::json::parse(f);
    EXPECT_EQ(j.at("format"), "simp-kidnap");
    EXPECT_DOUBLE_EQ(j.at("t_s").get<double>(), gt[100].t_s);
    EXPECT_DOUBLE_EQ(j.at("t_from_start_s").get<double>(), 10.0);
    EXPECT_EQ(j.at("step").get<int>(), 100);
    EXPECT_DOUBLE_EQ(j.at("from").at("x").get<double>(), s.kidnap->from.x);
    EXPECT_DOUBLE_EQ(j.at("from").at("phi").get<double>(), s.kidnap->from.phi);
    EXPECT_DOUBLE_EQ(j.at("to").at("y").get<double>(), s.kidnap->to.y);
    EXPECT_NEAR(j.at("jump_m").get<double>(), planarDistance(gt[99].pose, gt[100].pose), 1e-5);
}

TEST(SimKidnap, OwnRandomStreamLeavesEverythingBeforeItUnchanged) {
    const auto w = smallOffice();
    const auto p = shortRun();
    auto pk = p;
    pk.kidnap_at_s = 10.0;
    auto p_off = p;
    p_off.kidnap_at_s = -5;  // the .ini's "off"
    const std::string plain = simp::sim::test::clearedDir("kidnap_plain"), off = simp::sim::test::clearedDir("kidnap_off"),
                      k1 = simp::sim::test::clearedDir("kidnap_k1"), k2 = simp::sim::test::clearedDir("kidnap_k2");
    simp::sim::simulateSequence(w, p, 9, plain);
    simp::sim::simulateSequence(w, p_off, 9, off);
    simp::sim::simulateSequence(w, pk, 9, k1);
    simp::sim::simulateSequence(w, pk, 9, k2);
    for (const char* f : {"sequence.rawlog", "groundtruth.tum", "overview.png", "changes.json", "world/objects.json"}) {
        EXPECT_EQ(slurp(plain + "/" + f), slurp(off + "/" + f)) << f;
        EXPECT_EQ(slurp(k1 + "/" + f), slurp(k2 + "/" + f)) << f << ": a kidnap run is not reproducible";
    }
    EXPECT_FALSE(std::filesystem::exists(plain + "/kidnap.json"));
    EXPECT_EQ(slurp(k1 + "/kidnap.json"), slurp(k2 + "/kidnap.json"));

    // Up to the teleport (pose 100, step 100) the two runs are the same bytes: had the kidnap drawn
    // from the trajectory's, odometry's or detector's stream, the poses or detections would differ.
    std::vector<std::uint64_t> end_plain, end_k;
    readOdometry(plain + "/sequence.rawlog", &end_plain);
    readOdometry(k1 + "/sequence.rawlog", &end_k);
    ASSERT_EQ(end_plain.size(), 200u);
    ASSERT_EQ(end_k.size(), 200u);
    ASSERT_EQ(end_plain[98], end_k[98]);
    const std::string raw_plain = slurp(plain + "/sequence.rawlog"), raw_k = slurp(k1 + "/sequence.rawlog");
    EXPECT_EQ(raw_plain.substr(0, end_plain[98]), raw_k.substr(0, end_k[98])) << "steps 1-99 differ";
    EXPECT_NE(raw_plain, raw_k);
    const auto gt_plain = simp::io::readTum(plain + "/groundtruth.tum"), gt_k = simp::io::readTum(k1 + "/groundtruth.tum");
    for (std::size_t k = 0; k < 100; ++k) {
        EXPECT_EQ(gt_plain[k].pose.x, gt_k[k].pose.x) << "pose " << k;
        EXPECT_EQ(gt_plain[k].pose.phi, gt_k[k].pose.phi) << "pose " << k;
    }
    EXPECT_GT(planarDistance(gt_plain[100].pose, gt_k[100].pose), 1.0);
}

TEST(SimKidnap, NewPoseIsFreeReachableAndFarEnough) {
    // One room 10 m x 3 m: a pocket x < 3 m closed off by a wall, and the drivable rest (as in
    // SimCoverage.GoalsLieWhereTheRobotCanDrive). Poses are only drawn in the drivable part.
    simp::sim::Raster r;
    r.nx = 200;
    r.ny = 60;
    r.resolution_m = 0.05;
    r.blocked.assign(static_cast<std::size_t>(r.nx * r.ny), 0);
    for (int cy = 0; cy < r.ny; ++cy)
        for (int cx = 0; cx < r.nx; ++cx)
            r.set(cx, cy, cx == 0 || cy == 0 || cx == r.nx - 1 || cy == r.ny - 1 || cx == 60);
    const auto dist = simp::sim::clearance(r);
    simp::sim::Rng rng(4);
    const Eigen::Vector2d from(4.0, 1.5);
    double min_x = 1e9, max_x = -1e9;
    for (int i = 0; i < 200; ++i) {
        const auto pose = simp::sim::drawKidnapPose(r, from, 3.0, 0.2, rng);
        ASSERT_TRUE(pose.has_value());
        EXPECT_GE(std::hypot(pose->x - from.x(), pose->y - from.y()), 3.0);
        const std::size_t cell = static_cast<std::size_t>(r.cellY(pose->y)) * r.nx + r.cellX(pose->x);
        EXPECT_GE(dist[cell], 0.2);
        EXPECT_GT(pose->x, 3.05) << "in the closed-off pocket";
        EXPECT_GE(pose->phi, -M_PI);
        EXPECT_LT(pose->phi, M_PI);
        min_x = std::min(min_x, pose->x), max_x = std::max(max_x, pose->x);
    }
    EXPECT_GT(max_x - min_x, 1.5);  // spread over the area, not one fixed cell
    EXPECT_FALSE(simp::sim::drawKidnapPose(r, from, 20.0, 0.2, rng).has_value());  // nothing 20 m away
}

TEST(SimKidnap, ImpossibleRequestsAreNamed) {
    const auto w = smallOffice();
    auto p = shortRun();
    p.kidnap_at_s = 25;  // beyond the 20 s
    try {
        simp::sim::simulateSequence(w, p, 1, simp::sim::test::clearedDir("kidnap_late"));
        FAIL() << "no error for a kidnap after the end";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("kidnap_at_s"), std::string::npos) << e.what();
    }
    p.kidnap_at_s = 5;
    p.kidnap_min_distance_m = 500;  // farther than the office is wide
    try {
        simp::sim::simulateSequence(w, p, 1, simp::sim::test::clearedDir("kidnap_far"));
        FAIL() << "no error for a kidnap with nowhere to go";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("kidnap"), std::string::npos) << e.what();
    }
}

}  // namespace
