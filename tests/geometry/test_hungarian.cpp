/// Tests of simp/geometry/Hungarian.h: optimality against brute force on seeded random
/// rectangular matrices, edge shapes and bad input.
#include <simp/geometry/Hungarian.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <string>

namespace simp::geometry {
namespace {

/// Minimum total cost over all assignments of min(R, C) distinct pairs, by enumeration.
double bruteForceMinimum(const Eigen::MatrixXd& cost) {
    const bool wide = cost.rows() <= cost.cols();
    const Eigen::MatrixXd m = wide ? cost : Eigen::MatrixXd(cost.transpose());
    std::vector<int> cols(static_cast<std::size_t>(m.cols()));
    std::iota(cols.begin(), cols.end(), 0);
    double best = std::numeric_limits<double>::infinity();
    do {  // every permutation of the columns; the first R of them are the rows' columns
        double total = 0.0;
        for (Eigen::Index r = 0; r < m.rows(); ++r) total += m(r, cols[static_cast<std::size_t>(r)]);
        best = std::min(best, total);
    } while (std::next_permutation(cols.begin(), cols.end()));
    return best;
}

void expectValidAssignment(const Eigen::MatrixXd& cost, const std::vector<int>& a) {
    ASSERT_EQ(static_cast<Eigen::Index>(a.size()), cost.rows());
    std::set<int> used;
    for (const int c : a) {
        if (c < 0) continue;
        EXPECT_LT(c, cost.cols());
        EXPECT_TRUE(used.insert(c).second) << "column " << c << " assigned twice";
    }
    EXPECT_EQ(static_cast<Eigen::Index>(used.size()), std::min(cost.rows(), cost.cols()));
}

TEST(Hungarian, KnownSquareCase) {
    Eigen::MatrixXd cost(3, 3);
    cost << 4, 1, 3,  //
        2, 0, 5,      //
        3, 2, 2;
    // Optimum 1 + 2 + 2 = 5: row 0 -> col 1, row 1 -> col 0, row 2 -> col 2.
    const std::vector<int> a = solveAssignment(cost);
    EXPECT_EQ(a, (std::vector<int>{1, 0, 2}));
    EXPECT_DOUBLE_EQ(assignmentCost(cost, a), 5.0);
}

TEST(Hungarian, AgreesWithBruteForceOnRandomRectangularMatrices) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> value(-1.0, 3.0);
    std::uniform_int_distribution<int> small(0, 4);
    int checked = 0;
    for (int rows = 1; rows <= 6; ++rows) {
        for (int cols = 1; cols <= 6; ++cols) {
            for (int trial = 0; trial < 20; ++trial) {
                Eigen::MatrixXd cost(rows, cols);
                // Half the matrices take small integers, so ties between optima are common.
                for (int r = 0; r < rows; ++r)
                    for (int c = 0; c < cols; ++c) cost(r, c) = trial % 2 ? value(rng) : small(rng);
                const std::vector<int> a = solveAssignment(cost);
                expectValidAssignment(cost, a);
                EXPECT_NEAR(assignmentCost(cost, a), bruteForceMinimum(cost), 1e-12)
                    << rows << "x" << cols << " trial " << trial << "\n" << cost;
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 36 * 20);
}

TEST(Hungarian, EmptyAndDegenerateShapes) {
    EXPECT_TRUE(solveAssignment(Eigen::MatrixXd(0, 0)).empty());
    EXPECT_TRUE(solveAssignment(Eigen::MatrixXd(0, 4)).empty());
    EXPECT_EQ(solveAssignment(Eigen::MatrixXd(3, 0)), (std::vector<int>{-1, -1, -1}));
    EXPECT_DOUBLE_EQ(assignmentCost(Eigen::MatrixXd(3, 0), {-1, -1, -1}), 0.0);
}

TEST(Hungarian, OneRowPicksTheCheapestColumn) {
    Eigen::MatrixXd row(1, 5);
    row << 3.0, 0.5, 2.0, -1.0, 4.0;
    EXPECT_EQ(solveAssignment(row), (std::vector<int>{3}));
    // One column: only the cheapest row is assigned.
    EXPECT_EQ(solveAssignment(row.transpose()), (std::vector<int>{-1, -1, -1, 0, -1}));
}

TEST(Hungarian, LargerDiagonalOptimum) {
    // cost(r, c) = |r - c| has the unique optimum r -> r of cost 0 (any other permutation
    // moves some row off the diagonal). 60 x 80 runs the O(n^2 m) search quickly.
    Eigen::MatrixXd cost(60, 80);
    for (int r = 0; r < 60; ++r)
        for (int c = 0; c < 80; ++c) cost(r, c) = std::abs(r - c);
    const std::vector<int> a = solveAssignment(cost);
    for (int r = 0; r < 60; ++r) EXPECT_EQ(a[static_cast<std::size_t>(r)], r);
}

TEST(Hungarian, NonFiniteCostThrowsNamingTheEntry) {
    Eigen::MatrixXd cost = Eigen::MatrixXd::Ones(2, 3);
    cost(1, 2) = std::numeric_limits<double>::quiet_NaN();
    try {
        solveAssignment(cost);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("cost(1, 2)"), std::string::npos) << e.what();
    }
    cost(1, 2) = std::numeric_limits<double>::infinity();
    EXPECT_THROW(solveAssignment(cost), std::invalid_argument);
}

TEST(Hungarian, AssignmentCostRejectsMismatchedAssignments) {
    const Eigen::MatrixXd cost = Eigen::MatrixXd::Ones(2, 3);
    EXPECT_THROW(assignmentCost(cost, {0}), std::invalid_argument);
    EXPECT_THROW(assignmentCost(cost, {0, 3}), std::invalid_argument);
    EXPECT_DOUBLE_EQ(assignmentCost(cost, {2, -1}), 1.0);
}

}  // namespace
}  // namespace simp::geometry
