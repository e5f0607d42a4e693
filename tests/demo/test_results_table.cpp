// results.md of simp-demo: a failed run reports no convergence time and no ATE.
#include <gtest/gtest.h>
#include <simp/demo/DemoApp.h>

#include <sstream>
#include <string>
#include <vector>

using simp::demo::DemoRun;

namespace {

/// The cells of the table row of run `name` (without the outer pipes).
std::vector<std::string> rowOf(const std::string& table, const std::string& name) {
    std::istringstream lines(table);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("| " + name + " |", 0) != 0) continue;
        std::vector<std::string> cells;
        std::istringstream s(line.substr(1));
        for (std::string cell; std::getline(s, cell, '|');) {
            cell.erase(0, cell.find_first_not_of(' '));
            cell.erase(cell.find_last_not_of(' ') + 1);
            cells.push_back(cell);
        }
        return cells;
    }
    return {};
}

}  // namespace

TEST(DemoResultsTable, FailedRunsShowNoConvergenceOrAte) {
    DemoRun ok{"R1", 0.0, true, true, 12.34, 0.081, 0.0123, 90.0};
    DemoRun diverged{"R2", 0.15, false, true, 0.5, 4.06, 1.2, 90.0};  // converged at 0.5 s, then lost
    DemoRun never{"R3", 0.3, false, false, -1, -1, -1, 90.0};
    const std::string table = simp::demo::resultsTable({ok, diverged, never});

    const auto r1 = rowOf(table, "R1");
    ASSERT_EQ(r1.size(), 7u) << table;
    EXPECT_EQ(r1[2], "yes");
    EXPECT_EQ(r1[3], "12.3");
    EXPECT_EQ(r1[4], "0.081");
    EXPECT_EQ(r1[5], "0.012");

    const auto r2 = rowOf(table, "R2");
    ASSERT_EQ(r2.size(), 7u) << table;
    EXPECT_EQ(r2[2], "failed (diverged)");
    EXPECT_EQ(r2[3], "—");
    EXPECT_EQ(r2[4], "—");
    EXPECT_EQ(r2[5], "—");
    EXPECT_EQ(table.find("4.06"), std::string::npos) << table;

    const auto r3 = rowOf(table, "R3");
    ASSERT_EQ(r3.size(), 7u) << table;
    EXPECT_EQ(r3[2], "failed (never converged)");
    EXPECT_EQ(r3[4], "—");
    EXPECT_EQ(r3[6], "90.0");
}

TEST(DemoKidnapTable, AFailedKidnapShowsWhatHappenedAndNoAte) {
    simp::demo::DemoKidnapRun ok;
    ok.kidnap_at_s = 45;
    ok.lost_after_s = 1.2;
    ok.relocalized_after_s = 14.5;
    ok.after_ate_trans_m = 0.0912;
    ok.after_ate_rot_rad = 0.0301;
    ok.success = true;
    simp::demo::DemoKidnapRun never = ok;
    never.name = "K2";
    never.relocalized_after_s = -1;
    never.success = false;
    const std::string table = simp::demo::kidnapTable({ok, never});
    const auto r1 = rowOf(table, "K1");
    ASSERT_EQ(r1.size(), 8u) << table;
    EXPECT_EQ(r1[1], "15 %");
    EXPECT_EQ(r1[2], "45.0");
    EXPECT_EQ(r1[3], "1.2");
    EXPECT_EQ(r1[4], "14.5");
    EXPECT_EQ(r1[5], "0.091");
    EXPECT_EQ(r1[6], "0.030");
    EXPECT_EQ(r1[7], "yes");
    const auto r2 = rowOf(table, "K2");
    ASSERT_EQ(r2.size(), 8u) << table;
    EXPECT_EQ(r2[3], "1.2");
    EXPECT_EQ(r2[4], "—");
    EXPECT_EQ(r2[5], "—");  // an ATE after a failed relocalization is not a result
    EXPECT_EQ(r2[7], "no");
}
