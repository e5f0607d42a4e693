/// \file SessionTurn.cpp
/// Heading change of an earlier map object over a session (SessionTurn.h).
#include <mrpt/math/wrap2pi.h>
#include <simp/mapping/AssociationCost.h>
#include <simp/mapping/SessionTurn.h>

#include <cmath>

namespace simp::mapping {

TurnEstimate estimateTurn(const geometry::Box3D& before, const std::vector<SessionBox>& windows) {
    // On the 4-fold circle (angles x 4) a turn of 89 deg and one of -1 deg are 4 deg apart, as
    // the solids are.
    constexpr double kFold = 4.0;
    const double yaw0 = geometry::yawOf(before);
    std::vector<double> angles, weights;
    double c = 0, s = 0, w_sum = 0;
    for (const SessionBox& sb : windows) {
        if (!(sb.weight > 0)) continue;
        const double a =
            kFold * mrpt::math::wrapToPi(geometry::yawOf(closestEquivalent(sb.box, before.R)) - yaw0);
        angles.push_back(a);
        weights.push_back(sb.weight);
        c += sb.weight * std::cos(a), s += sb.weight * std::sin(a), w_sum += sb.weight;
    }
    TurnEstimate t;
    t.windows = static_cast<int>(angles.size());
    if (angles.empty()) return t;
    const double mean = std::atan2(s, c);
    t.turn_rad = mean / kFold;
    t.concentration = std::hypot(c, s) / w_sum;
    // Fisher (Statistical Analysis of Circular Data, 4.4): circular dispersion
    // (1 - rho_2) / (2 R^2), rho_2 the mean of cos 2(a - mean); the mean direction's standard
    // error is sqrt(dispersion / n).
    double rho2 = 0;
    for (std::size_t i = 0; i < angles.size(); ++i) rho2 += weights[i] * std::cos(2.0 * (angles[i] - mean));
    rho2 /= w_sum;
    const double r2 = std::max(t.concentration * t.concentration, 1e-12);
    const double dispersion = std::max(0.0, 1.0 - rho2) / (2.0 * r2);
    t.std_error_rad = std::sqrt(dispersion / static_cast<double>(angles.size())) / kFold;
    return t;
}

bool isTurned(const TurnEstimate& t, int min_windows, double min_turn_rad, double sigmas) {
    if (min_turn_rad <= 0 || t.windows < min_windows || t.concentration < kMinTurnConcentration) return false;
    const double a = std::abs(t.turn_rad);
    return a >= min_turn_rad && a >= sigmas * t.std_error_rad;
}

}  // namespace simp::mapping
