#pragma once
/// \file Hungarian.h
/// Minimum-cost assignment (Kuhn 1955, "the Hungarian method"; shortest augmenting
/// paths with potentials, Jonker-Volgenant style) for rectangular cost matrices:
/// the data association of detections to map objects (Eq. costfunc).

#include <Eigen/Core>
#include <vector>

namespace simp::geometry {

/// Minimum-cost assignment of rows to columns of an R x C cost matrix.
/// Every row is assigned a distinct column when R <= C; when R > C exactly C rows
/// are assigned and the others get -1. result[r] = column of row r, or -1.
/// Cost O(min(R,C)^2 * max(R,C)) time, O(R + C) extra memory.
/// \throw std::invalid_argument when a cost is not finite (NaN or +-inf), naming the entry.
std::vector<int> solveAssignment(const Eigen::MatrixXd& cost);

/// Total cost of an assignment (sum of cost(r, assignment[r]) over assigned rows).
/// \throw std::invalid_argument when assignment.size() != cost.rows() or a column is out of range.
double assignmentCost(const Eigen::MatrixXd& cost, const std::vector<int>& assignment);

}  // namespace simp::geometry
