#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <simp/io/StrictIni.h>
#include <simp/mapping/MappingOptions.h>

using namespace simp::mapping;

TEST(MappingOptions, DefaultsAreTheAuthors) {
    const MappingOptions o;
    EXPECT_DOUBLE_EQ(o.trigger_dist_m, 0.2);
    EXPECT_DOUBLE_EQ(o.trigger_angle_rad, 0.1);
    EXPECT_DOUBLE_EQ(o.tau_cost, 0.3);
    EXPECT_DOUBLE_EQ(o.truncation_threshold, 0.5);
    EXPECT_DOUBLE_EQ(o.min_local_support, 0.3);  // authors: purgeDetections, 0.3 x detc_cnt
    EXPECT_DOUBLE_EQ(o.filterOf("sink").min_confidence, 0.7);
    EXPECT_DOUBLE_EQ(o.filterOf("board").min_range_m, 1.5);
    EXPECT_DOUBLE_EQ(o.filterOf("cabinet").max_range_m, 5.0);
    EXPECT_LE(o.filterOf("chair").max_range_m, 0.0);  // not mapped by the authors
    EXPECT_DOUBLE_EQ(o.filterOf("door").max_range_m, 4.0);  // project: doors are mapped (mapping.ini)
    EXPECT_DOUBLE_EQ(o.crossRoomMergeRadiusOf("door"), 0.5);
    EXPECT_DOUBLE_EQ(o.crossRoomMergeRadiusOf("table"), 0.0);
    EXPECT_DOUBLE_EQ(o.filterOf("unknown thing").min_confidence, o.default_filter.min_confidence);
}

TEST(MappingOptions, LoadsKeysAndPerClassLists) {
    mrpt::config::CConfigFileMemory ini(
        "[mapping]\n"
        "tau_cost = 0.25\n"
        "trigger_dist_m = 0.1\n"
        "min_local_support = 0.5\n"
        "room_update_policy = all\n"
        "update_removal_alpha = 0.05\n"
        "update_reassociate_max_seen_fraction = 0.4\n"
        "class_min_confidence = potted plant: 0.5, sofa:0.6\n"
        "class_max_range_m = lamp:3.5\n");
    MappingOptions o;
    o.loadFromConfigFile(ini, "mapping");
    EXPECT_DOUBLE_EQ(o.tau_cost, 0.25);
    EXPECT_DOUBLE_EQ(o.trigger_dist_m, 0.1);
    EXPECT_DOUBLE_EQ(o.min_local_support, 0.5);
    EXPECT_DOUBLE_EQ(o.trigger_angle_rad, 0.1);  // absent key keeps the default
    EXPECT_EQ(o.room_policy, RoomUpdatePolicy::All);
    EXPECT_DOUBLE_EQ(o.update_removal_alpha, 0.05);
    EXPECT_DOUBLE_EQ(o.update_reassociate_max_seen_fraction, 0.4);
    EXPECT_DOUBLE_EQ(o.filterOf("potted plant").min_confidence, 0.5);
    EXPECT_DOUBLE_EQ(o.filterOf("potted plant").max_range_m, 4.5);  // other fields kept
    EXPECT_DOUBLE_EQ(o.filterOf("sofa").min_confidence, 0.6);
    EXPECT_DOUBLE_EQ(o.filterOf("lamp").max_range_m, 3.5);
    std::ostringstream dump;
    o.dumpToTextStream(dump);
    // the dump is MappingOptions::table()'s: "key = value  // meaning", readable back as an .ini
    EXPECT_NE(dump.str().find("\ntau_cost                             = 0.25  // "), std::string::npos);
}

TEST(MappingOptions, BadValuesNameTheKey) {
    auto expectThrowNaming = [](const std::string& text, const std::string& key) {
        MappingOptions o;
        try {
            const simp::io::StrictIni ini("[mapping]\n" + text + "\n", "m.ini");
            o.loadFromConfigFile(ini, "mapping");
            ini.checkUnknown();
            FAIL() << "no exception for " << text;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
        }
    };
    expectThrowNaming("tau_cost = abc", "tau_cost");
    expectThrowNaming("tau_cost = 2", "tau_cost");
    expectThrowNaming("trigger_dist_m = nan", "trigger_dist_m");
    expectThrowNaming("zbuffer_downscale = 2.5", "zbuffer_downscale");
    expectThrowNaming("room_update_policy = sometimes", "room_update_policy");
    expectThrowNaming("update_removal_alpha = 1.5", "update_removal_alpha");
    expectThrowNaming("update_reassociate_max_seen_fraction = -0.1", "update_reassociate_max_seen_fraction");
    expectThrowNaming("class_min_confidence = sink 0.7", "class_min_confidence");
    expectThrowNaming("class_min_confidence = sink:high", "class_min_confidence");
    expectThrowNaming("class_min_confidence = sink:1.5", "sink");
    expectThrowNaming("duplicate_tau_cost = 1.5", "duplicate_tau_cost");
    expectThrowNaming("duplicate_min_overlap = -0.1", "duplicate_min_overlap");
    expectThrowNaming("distinct_codetected_frames = -1", "distinct_codetected_frames");
    expectThrowNaming("distinct_codetected_frames = 2.5", "distinct_codetected_frames");
    expectThrowNaming("twin_max_support_ratio = 2", "twin_max_support_ratio");
    expectThrowNaming("twin_min_likelihood = -0.05", "twin_min_likelihood");
    expectThrowNaming("skip_needs_no_detection = sometimes", "skip_needs_no_detection");
    expectThrowNaming("duplicate_center_radius_m = wide", "duplicate_center_radius_m");
    expectThrowNaming("class_duplicate_center_radius_m = sofa", "class_duplicate_center_radius_m");
    expectThrowNaming("class_duplicate_center_radius_m = sofa:-1", "sofa");
    expectThrowNaming("min_local_support = -0.3", "min_local_support");
    expectThrowNaming("min_local_support = often", "min_local_support");
    expectThrowNaming("min_confirmed_matches = 0", "min_confirmed_matches");
    expectThrowNaming("min_confirmed_matches = 2.5", "min_confirmed_matches");
    expectThrowNaming("wall_align = maybe", "wall_align");
    expectThrowNaming("wall_align_max_enclosed_unknown_m2 = -1", "wall_align_max_enclosed_unknown_m2");
    expectThrowNaming("class_wall_align_max_gap_m = board", "class_wall_align_max_gap_m");
    expectThrowNaming("class_wall_align_max_gap_m = board:-0.1", "board");
    expectThrowNaming("tau_cots = 0.3", "m.ini: [mapping] unknown key 'tau_cots'");
    expectThrowNaming("wall_align_rays = 1", "wall_align_rays");
    expectThrowNaming("wall_align_max_yaw_rad = 2", "wall_align_max_yaw_rad");
    expectThrowNaming("wall_align_max_penetration_m = nan", "wall_align_max_penetration_m");
    expectThrowNaming("wall_align_max_residual_m = -1", "wall_align_max_residual_m");
}

TEST(MappingOptions, WallAlignmentAndConfirmationKeys) {
    const MappingOptions defaults;
    EXPECT_EQ(defaults.wall_align, WallAlignMode::Auto);
    EXPECT_EQ(defaults.min_confirmed_matches, 3);
    ASSERT_TRUE(defaults.wallAlignmentOf("board").has_value());
    EXPECT_DOUBLE_EQ(defaults.wallAlignmentOf("board")->max_gap_m, 0.3);
    EXPECT_FALSE(defaults.wallAlignmentOf("potted plant").has_value());  // plants stand free
    EXPECT_FALSE(defaults.wallAlignmentOf("sofa").has_value());          // often a little off the wall
    EXPECT_TRUE(defaults.wallAlignmentOf("cabinet").has_value());
    mrpt::config::CConfigFileMemory ini(
        "[mapping]\n"
        "min_confirmed_matches = 5\n"
        "class_wall_align_max_gap_m = board:0.2, potted plant:0.1\n"
        "wall_align_max_penetration_m = 0.15\n"
        "wall_align_max_yaw_rad = 0.1\n"
        "wall_align_max_residual_m = 0.05\n"
        "wall_align_rays = 7\n"
        "remove_class_bias = false\n"
        "hide_objects_in_walls = false\n");
    MappingOptions o;
    EXPECT_TRUE(o.remove_class_bias);
    EXPECT_TRUE(o.hide_objects_in_walls);
    o.loadFromConfigFile(ini, "mapping");
    EXPECT_FALSE(o.remove_class_bias);
    EXPECT_FALSE(o.hide_objects_in_walls);
    EXPECT_EQ(o.min_confirmed_matches, 5);
    const auto board = o.wallAlignmentOf("board");
    ASSERT_TRUE(board.has_value());
    EXPECT_DOUBLE_EQ(board->max_gap_m, 0.2);
    EXPECT_DOUBLE_EQ(board->max_penetration_m, 0.15);
    EXPECT_DOUBLE_EQ(board->max_yaw_rad, 0.1);
    EXPECT_DOUBLE_EQ(board->max_residual_m, 0.05);
    EXPECT_EQ(board->rays_per_side, 7);
    EXPECT_TRUE(o.wallAlignmentOf("potted plant").has_value());
    EXPECT_FALSE(o.wallAlignmentOf("cabinet").has_value());  // the list replaces the default list
    // An empty list aligns no class; wall_align = false switches the prior off.
    mrpt::config::CConfigFileMemory none("[mapping]\nclass_wall_align_max_gap_m =\n");
    MappingOptions n;
    n.loadFromConfigFile(none, "mapping");
    EXPECT_FALSE(n.wallAlignmentOf("board").has_value());
    mrpt::config::CConfigFileMemory off("[mapping]\nwall_align = false\n");
    MappingOptions f;
    f.loadFromConfigFile(off, "mapping");
    EXPECT_EQ(f.wall_align, WallAlignMode::Off);
    EXPECT_FALSE(f.wallAlignmentOf("board").has_value());
    mrpt::config::CConfigFileMemory on("[mapping]\nwall_align = true\nwall_align_max_enclosed_unknown_m2 = 4\n");
    f.loadFromConfigFile(on, "mapping");
    EXPECT_EQ(f.wall_align, WallAlignMode::On);
    EXPECT_DOUBLE_EQ(f.wall_align_max_enclosed_unknown_m2, 4.0);
}

TEST(MappingOptions, DuplicateRulesLoadWithPerClassRadius) {
    const MappingOptions defaults;
    EXPECT_DOUBLE_EQ(defaults.duplicateCenterRadiusOf("desk"), 0.5);  // the authors' centerMerge
    EXPECT_DOUBLE_EQ(defaults.duplicateCenterRadiusOf("sofa"), 1.0);
    mrpt::config::CConfigFileMemory ini(
        "[mapping]\n"
        "duplicate_center_radius_m = 0.3\n"
        "class_duplicate_center_radius_m = desk:0.8, potted plant:0.2\n"
        "duplicate_tau_cost = 0.6\n"
        "duplicate_max_distance_m = 1.2\n"
        "duplicate_min_overlap = 0.25\n");
    MappingOptions o;
    o.loadFromConfigFile(ini, "mapping");
    EXPECT_DOUBLE_EQ(o.duplicateCenterRadiusOf("desk"), 0.8);
    EXPECT_DOUBLE_EQ(o.duplicateCenterRadiusOf("potted plant"), 0.2);
    EXPECT_DOUBLE_EQ(o.duplicateCenterRadiusOf("sofa"), 0.3);  // the list replaces the default list
    EXPECT_DOUBLE_EQ(o.duplicate_tau_cost, 0.6);
    EXPECT_DOUBLE_EQ(o.duplicate_max_distance_m, 1.2);
    EXPECT_DOUBLE_EQ(o.duplicate_min_overlap, 0.25);
}

TEST(MappingOptions, TheShippedIniLoadsAndMatchesTheDefaults) {
    mrpt::config::CConfigFile ini(std::string(SIMP_SOURCE_DIR) + "/config_ini/mapping.ini");
    MappingOptions o;
    o.loadFromConfigFile(ini, "mapping");
    // simp-map without --config uses MappingOptions(): every field printed to the last digit (17
    // significant digits tell doubles apart), so the defaults and mapping.ini cannot drift apart.
    std::ostringstream a, b;
    a.precision(17);
    b.precision(17);
    o.dumpToTextStream(a);
    MappingOptions().dumpToTextStream(b);
    EXPECT_EQ(a.str(), b.str());
}
