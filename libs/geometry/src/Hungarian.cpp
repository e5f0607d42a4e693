#include <simp/geometry/Hungarian.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace simp::geometry {
namespace {

/// Rows <= columns. Successive shortest augmenting paths with dual potentials u (rows)
/// and v (columns): each row is added by a Dijkstra-like search over reduced costs
/// cost(i, j) - u(i) - v(j) >= 0, O(n) iterations of O(m) each, O(n^2 m) in all.
std::vector<int> solveWide(const Eigen::MatrixXd& cost) {
    const int n = static_cast<int>(cost.rows()), m = static_cast<int>(cost.cols());
    constexpr double kInf = std::numeric_limits<double>::infinity();
    // 1-based indices; column 0 is a virtual column holding the row being inserted.
    std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0), min_reduced(m + 1);
    std::vector<int> row_of_col(m + 1, 0), way(m + 1, 0);
    std::vector<char> used(m + 1);
    for (int i = 1; i <= n; ++i) {
        row_of_col[0] = i;
        int j0 = 0;
        std::fill(min_reduced.begin(), min_reduced.end(), kInf);
        std::fill(used.begin(), used.end(), 0);
        do {
            used[j0] = 1;
            const int i0 = row_of_col[j0];
            double delta = kInf;
            int j1 = 0;
            for (int j = 1; j <= m; ++j) {
                if (used[j]) continue;
                const double reduced = cost(i0 - 1, j - 1) - u[i0] - v[j];
                if (reduced < min_reduced[j]) {
                    min_reduced[j] = reduced;
                    way[j] = j0;
                }
                if (min_reduced[j] < delta) {
                    delta = min_reduced[j];
                    j1 = j;
                }
            }
            for (int j = 0; j <= m; ++j) {
                if (used[j]) {
                    u[row_of_col[j]] += delta;
                    v[j] -= delta;
                } else {
                    min_reduced[j] -= delta;
                }
            }
            j0 = j1;
        } while (row_of_col[j0] != 0);
        do {  // augment along the alternating path
            const int j1 = way[j0];
            row_of_col[j0] = row_of_col[j1];
            j0 = j1;
        } while (j0 != 0);
    }
    std::vector<int> result(n, -1);
    for (int j = 1; j <= m; ++j)
        if (row_of_col[j] != 0) result[row_of_col[j] - 1] = j - 1;
    return result;
}

}  // namespace

std::vector<int> solveAssignment(const Eigen::MatrixXd& cost) {
    for (Eigen::Index r = 0; r < cost.rows(); ++r)
        for (Eigen::Index c = 0; c < cost.cols(); ++c)
            if (!std::isfinite(cost(r, c)))
                throw std::invalid_argument("simp::geometry::solveAssignment: cost(" + std::to_string(r) + ", " +
                                            std::to_string(c) + ") = " + std::to_string(cost(r, c)) +
                                            " is not finite");
    if (cost.rows() == 0) return {};
    if (cost.cols() == 0) return std::vector<int>(static_cast<std::size_t>(cost.rows()), -1);
    if (cost.rows() <= cost.cols()) return solveWide(cost);
    // More rows than columns: assign columns to rows on the transpose, then invert.
    const std::vector<int> row_of_col = solveWide(cost.transpose());
    std::vector<int> result(static_cast<std::size_t>(cost.rows()), -1);
    for (std::size_t c = 0; c < row_of_col.size(); ++c) result[static_cast<std::size_t>(row_of_col[c])] = static_cast<int>(c);
    return result;
}

double assignmentCost(const Eigen::MatrixXd& cost, const std::vector<int>& assignment) {
    if (static_cast<Eigen::Index>(assignment.size()) != cost.rows())
        throw std::invalid_argument("simp::geometry::assignmentCost: assignment has " +
                                    std::to_string(assignment.size()) + " entries for " +
                                    std::to_string(cost.rows()) + " cost rows");
    double total = 0.0;
    for (std::size_t r = 0; r < assignment.size(); ++r) {
        const int c = assignment[r];
        if (c < 0) continue;
        if (c >= cost.cols())
            throw std::invalid_argument("simp::geometry::assignmentCost: row " + std::to_string(r) +
                                        " assigned to column " + std::to_string(c) + " of " +
                                        std::to_string(cost.cols()));
        total += cost(static_cast<Eigen::Index>(r), c);
    }
    return total;
}

}  // namespace simp::geometry
