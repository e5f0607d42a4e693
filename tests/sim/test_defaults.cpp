/// simp-sim without --config runs exactly as with config_ini/sim.ini: every field the .ini sets is
/// compared with the compiled-in default (exact equality), and both give byte-identical sequences.

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/io/vector_loadsave.h>
#include <simp/sim/OfficeLayout.h>
#include <simp/sim/SimApp.h>
#include <simp/sim/SimParams.h>

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace {

const std::string kSimIni = std::string(SIMP_SOURCE_DIR) + "/config_ini/sim.ini";

#define SIMP_EXPECT_SAME(field) EXPECT_EQ(a.field, b.field) << #field

void expectSame(const simp::sim::OfficeParams& a, const simp::sim::OfficeParams& b) {
    SIMP_EXPECT_SAME(rooms);
    SIMP_EXPECT_SAME(size_m2);
    SIMP_EXPECT_SAME(resolution_m);
    SIMP_EXPECT_SAME(wall_thickness_m);
    SIMP_EXPECT_SAME(corridor_width_m);
    SIMP_EXPECT_SAME(door_width_m);
    SIMP_EXPECT_SAME(room_width_min_m);
    SIMP_EXPECT_SAME(room_width_max_m);
    SIMP_EXPECT_SAME(room_depth_min_m);
    SIMP_EXPECT_SAME(room_depth_max_m);
    SIMP_EXPECT_SAME(max_rooms_per_side);
    SIMP_EXPECT_SAME(kitchen_every_n_rooms);
    SIMP_EXPECT_SAME(meeting_fraction);
}

void expectSame(const simp::sim::SimParams& a, const simp::sim::SimParams& b) {
    SIMP_EXPECT_SAME(duration_s);
    SIMP_EXPECT_SAME(epoch_s);
    SIMP_EXPECT_SAME(progress);
    SIMP_EXPECT_SAME(kidnap_at_s);
    SIMP_EXPECT_SAME(kidnap_min_distance_m);
    SIMP_EXPECT_SAME(trajectory.robot_radius_m);
    SIMP_EXPECT_SAME(trajectory.clearance_m);
    SIMP_EXPECT_SAME(trajectory.speed_min_mps);
    SIMP_EXPECT_SAME(trajectory.speed_max_mps);
    SIMP_EXPECT_SAME(trajectory.turn_rate_radps);
    SIMP_EXPECT_SAME(trajectory.turn_in_place_rad);
    SIMP_EXPECT_SAME(trajectory.spin_probability);
    SIMP_EXPECT_SAME(trajectory.waypoint_tolerance_m);
    SIMP_EXPECT_SAME(trajectory.coverage);
    SIMP_EXPECT_SAME(trajectory.coverage_part_m);
    SIMP_EXPECT_SAME(odometry.rate_hz);
    SIMP_EXPECT_SAME(odometry.a1);
    SIMP_EXPECT_SAME(odometry.a2);
    SIMP_EXPECT_SAME(odometry.a3);
    SIMP_EXPECT_SAME(odometry.a4);
    SIMP_EXPECT_SAME(odometry.minStdXY);
    SIMP_EXPECT_SAME(odometry.minStdPHI);
    SIMP_EXPECT_SAME(odometry.noise_scale);
    SIMP_EXPECT_SAME(cameras.count);
    SIMP_EXPECT_SAME(cameras.first_yaw_deg);
    SIMP_EXPECT_SAME(cameras.mount_radius_m);
    SIMP_EXPECT_SAME(cameras.height_m);
    SIMP_EXPECT_SAME(cameras.pitch_down_deg);
    SIMP_EXPECT_SAME(cameras.intrinsics.ncols);
    SIMP_EXPECT_SAME(cameras.intrinsics.nrows);
    SIMP_EXPECT_SAME(cameras.intrinsics.fx());
    SIMP_EXPECT_SAME(cameras.intrinsics.fy());
    SIMP_EXPECT_SAME(cameras.intrinsics.cx());
    SIMP_EXPECT_SAME(cameras.intrinsics.cy());
    SIMP_EXPECT_SAME(cameras.rate_hz);
    SIMP_EXPECT_SAME(visibility.min_range_m);
    SIMP_EXPECT_SAME(visibility.max_range_m);
    SIMP_EXPECT_SAME(visibility.default_max_range_m);
    SIMP_EXPECT_SAME(visibility.min_inside_fraction);
    SIMP_EXPECT_SAME(visibility.render_downscale);
    SIMP_EXPECT_SAME(visibility.min_unwalled_fraction);
    SIMP_EXPECT_SAME(visibility.wall_depth_margin_m);
    SIMP_EXPECT_SAME(visibility.self_margin_m);
    SIMP_EXPECT_SAME(visibility.max_occluded_fraction);
    SIMP_EXPECT_SAME(detector.detection_probability);
    SIMP_EXPECT_SAME(detector.default_noise_std_m);
    SIMP_EXPECT_SAME(detector.z_std_m);
    SIMP_EXPECT_SAME(detector.size_std_fraction);
    SIMP_EXPECT_SAME(detector.yaw_std_rad);
    SIMP_EXPECT_SAME(detector.wrong_class_probability);
    SIMP_EXPECT_SAME(detector.confidence_true_mean);
    SIMP_EXPECT_SAME(detector.confidence_true_std);
    SIMP_EXPECT_SAME(detector.confidence_false_mean);
    SIMP_EXPECT_SAME(detector.confidence_false_std);
    SIMP_EXPECT_SAME(detector.min_confidence);
    SIMP_EXPECT_SAME(detector.reference_distance_m);
    SIMP_EXPECT_SAME(detector.persistent_variance_fraction);
    SIMP_EXPECT_SAME(detector.viewpoint_bin_deg);
    SIMP_EXPECT_SAME(detector.viewpoint_bin_m);
    SIMP_EXPECT_SAME(detector.noise_model_includes_extent);
    SIMP_EXPECT_SAME(detector.min_centre_noise_fraction);
    SIMP_EXPECT_SAME(false_positives.rate_per_frame);
    SIMP_EXPECT_SAME(false_positives.range_min_m);
    SIMP_EXPECT_SAME(false_positives.range_max_m);
    SIMP_EXPECT_SAME(people.count);
    SIMP_EXPECT_SAME(people.speed_min_mps);
    SIMP_EXPECT_SAME(people.speed_max_mps);
    SIMP_EXPECT_SAME(changes.fraction);
    SIMP_EXPECT_SAME(changes.shift_min_m);
    SIMP_EXPECT_SAME(changes.shift_max_m);
    SIMP_EXPECT_SAME(changes.rotation_std_deg);
    SIMP_EXPECT_SAME(changes.door_close_fraction);
    SIMP_EXPECT_SAME(lidar.enabled);
    SIMP_EXPECT_SAME(lidar.rate_hz);
    SIMP_EXPECT_SAME(lidar.fov_deg);
    SIMP_EXPECT_SAME(lidar.beams);
    SIMP_EXPECT_SAME(lidar.max_range_m);
    SIMP_EXPECT_SAME(lidar.range_std_m);
    SIMP_EXPECT_SAME(lidar.x_m);
    SIMP_EXPECT_SAME(lidar.y_m);
    SIMP_EXPECT_SAME(lidar.height_m);
    SIMP_EXPECT_SAME(lidar.yaw_deg);
}
#undef SIMP_EXPECT_SAME

void runSim(const std::vector<std::string>& args) {
    simp::sim::SimApp app;
    std::ostringstream out;
    if (app.initialize(args, out)) app.run(out);
}

}  // namespace

TEST(SimDefaults, CompiledInDefaultsEqualSimIniFieldByField) {
    mrpt::config::CConfigFile ini(kSimIni);
    simp::sim::OfficeParams office;
    office.loadFromConfig(ini, "office");
    expectSame(simp::sim::OfficeParams{}, office);
    simp::sim::SimParams seq;
    seq.loadFromConfig(ini);
    expectSame(simp::sim::SimParams{}, seq);
}

TEST(SimDefaults, WithoutConfigTheSequenceIsByteIdenticalToSimIni) {
    const fs::path dir = fs::path(SIMP_TEST_OUTPUT_DIR) / "sim" / "defaults";
    fs::remove_all(dir);
    const std::string w = (dir / "w").string();
    runSim({"world", "--builtin", "office", "--seed", "8", "--out", (dir / "w_plain").string(), "--rooms", "3"});
    runSim({"world", "--builtin", "office", "--seed", "8", "--out", w, "--rooms", "3", "--config", kSimIni});
    EXPECT_EQ(mrpt::io::file_get_contents((dir / "w_plain" / "objects.json").string()),
              mrpt::io::file_get_contents((dir / "w" / "objects.json").string()));
    runSim({"sequence", "--world", w, "--seed", "9", "--out", (dir / "q_plain").string(), "--duration", "6"});
    runSim({"sequence", "--world", w, "--seed", "9", "--out", (dir / "q_ini").string(), "--duration", "6", "--config",
            kSimIni});
    const auto plain = mrpt::io::file_get_contents((dir / "q_plain" / "sequence.rawlog").string());
    EXPECT_GT(plain.size(), 10000u);  // 6 s of odometry and four cameras' detections
    EXPECT_EQ(plain, mrpt::io::file_get_contents((dir / "q_ini" / "sequence.rawlog").string()));
    EXPECT_EQ(mrpt::io::file_get_contents((dir / "q_plain" / "groundtruth.tum").string()),
              mrpt::io::file_get_contents((dir / "q_ini" / "groundtruth.tum").string()));
}
