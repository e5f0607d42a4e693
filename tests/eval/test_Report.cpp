// The --json schemas of the contract and the Markdown table layout.
#include <gtest/gtest.h>
#include <simp/eval/Report.h>
#include <simp/geometry/Box3D.h>

#include <set>

using nlohmann::json;

namespace {

std::set<std::string> keysOf(const json& j) {
    std::set<std::string> k;
    for (auto it = j.begin(); it != j.end(); ++it) k.insert(it.key());
    return k;
}

}  // namespace

TEST(Report, TrajJsonHasExactlyTheContractKeys) {
    simp::eval::TrajMetrics m;
    m.converged = true;
    m.success = true;
    m.convergence_time_s = 3.0;
    m.ate_trans_m = 0.15;
    m.ate_rot_rad = 0.05;
    m.duration_s = 10.0;
    const json j = json::parse(simp::eval::toJson(m).dump());  // round trip through text
    EXPECT_EQ(keysOf(j), (std::set<std::string>{"success", "converged", "convergence_time_s", "ate_trans_m",
                                                 "ate_rot_rad", "duration_s"}));
    EXPECT_TRUE(j["success"].is_boolean());
    EXPECT_TRUE(j["converged"].is_boolean());
    EXPECT_DOUBLE_EQ(j["convergence_time_s"].get<double>(), 3.0);
    EXPECT_DOUBLE_EQ(j["ate_trans_m"].get<double>(), 0.15);
    EXPECT_DOUBLE_EQ(j["ate_rot_rad"].get<double>(), 0.05);
    EXPECT_DOUBLE_EQ(j["duration_s"].get<double>(), 10.0);
}

TEST(Report, TrajJsonNullsWhenNeverConverged) {
    simp::eval::TrajMetrics m;
    m.duration_s = 7.5;
    const json j = simp::eval::toJson(m);
    EXPECT_FALSE(j["success"].get<bool>());
    EXPECT_FALSE(j["converged"].get<bool>());
    EXPECT_TRUE(j["convergence_time_s"].is_null());
    EXPECT_TRUE(j["ate_trans_m"].is_null());
    EXPECT_TRUE(j["ate_rot_rad"].is_null());
    EXPECT_TRUE(j["duration_s"].is_number());
}

TEST(Report, MapJsonAndMarkdownLayout) {
    simp::eval::MapMetrics m;
    m.per_class["board"] = {2, 2, 2, 0.54, 0.3, 1.0, 0.94};
    m.per_class["table"] = {4, 3, 3, 0.76, 0.6, 1.0, 0.75};
    m.iou = 0.65;
    m.precision = 1.0;
    m.recall = 0.85;
    const json j = json::parse(simp::eval::toJson(m).dump());
    EXPECT_EQ(keysOf(j), (std::set<std::string>{"iou", "precision", "recall", "per_class"}));
    EXPECT_EQ(keysOf(j["per_class"]), (std::set<std::string>{"board", "table"}));
    for (const auto& [name, c] : j["per_class"].items()) {
        EXPECT_EQ(keysOf(c), (std::set<std::string>{"iou", "precision", "recall"})) << name;
        for (const auto& [k, v] : c.items()) EXPECT_TRUE(v.is_number()) << name << "." << k;
    }
    EXPECT_DOUBLE_EQ(j["per_class"]["table"]["recall"].get<double>(), 0.75);

    const std::string md = simp::eval::mapMarkdownTable(m);
    EXPECT_NE(md.find("| | board | table | AVG |"), std::string::npos) << md;
    EXPECT_NE(md.find("| IoU | 0.54 | 0.76 | 0.65 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| Pr | 1.00 | 1.00 | 1.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| Rc | 0.94 | 0.75 | 0.85 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| GT/pred/matched | 2/2/2 | 4/3/3 | 6/5/5 |"), std::string::npos) << md;
}
