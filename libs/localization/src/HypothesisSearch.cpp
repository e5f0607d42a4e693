#include <simp/localization/HypothesisSearch.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace simp::localization {
namespace {

/// Indices of `score` best first; ties by index (same input, same order).
std::vector<std::size_t> bestFirst(const std::vector<double>& score) {
    std::vector<std::size_t> order(score.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return score[a] > score[b]; });
    return order;
}

}  // namespace

HypothesisSearch::HypothesisSearch(const maps::CObjectMap& map, const DetectionPoseSampler& sampler,
                                   const HypothesisSearchParams& params)
    : m_map(map), m_sampler(sampler), m_params(params) {}

bool samePlace(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b, double max_distance_m, double max_turn_rad) {
    return std::hypot(a.x - b.x, a.y - b.y) <= max_distance_m &&
           std::abs(mrpt::math::wrapToPi(a.phi - b.phi)) <= max_turn_rad;
}

bool HypothesisSearch::distinct(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) const {
    return !samePlace(a, b, m_params.distinct_distance_m, m_params.distinct_heading_rad);
}

std::vector<Hypothesis> HypothesisSearch::search(const FitWindow& window,
                                                 const std::vector<WeightedObservation>& observations,
                                                 const mrpt::poses::CPose2D& odometry_now) const {
    std::vector<Hypothesis> out;
    if (!m_params.enabled || window.size() < m_params.min_window_detections) return out;
    std::vector<mrpt::math::TPose2D> candidates;
    if (m_params.pair_candidates > 0) {
        // Fits of the odometry frame, the robot now where odometry_now lands in it.
        for (const auto& world_T_odo : m_sampler.pairFits(window.placed(), m_params.pairs, m_params.pair_candidates)) {
            const auto now = (mrpt::poses::CPose2D(world_T_odo) + odometry_now).asTPose();
            if (m_sampler.freeSpace().isFree(now.x, now.y)) candidates.push_back(now);
        }
    }
    const auto singles = m_sampler.candidates(observations, m_params.max_candidates);
    candidates.insert(candidates.end(), singles.begin(), singles.end());
    if (candidates.empty()) return out;
    std::vector<double> score;
    window.scorePoses(m_map, candidates, odometry_now, score);

    // The best distinct candidates (greedy suppression of their neighbours) ...
    std::vector<Hypothesis> seeds;
    for (const std::size_t i : bestFirst(score)) {
        if (seeds.size() >= m_params.refine_top) break;
        const bool near_seed = std::any_of(seeds.begin(), seeds.end(), [&](const Hypothesis& h) { return !distinct(h.pose, candidates[i]); });
        if (!near_seed) seeds.push_back({candidates[i], score[i]});
    }
    // ... each refined: an exact fit of one noisy detection is off by its noise, the window pins
    // the pose down.
    for (auto& h : seeds) refine(window, odometry_now, h);
    std::stable_sort(seeds.begin(), seeds.end(),
                     [](const Hypothesis& a, const Hypothesis& b) { return a.log_likelihood > b.log_likelihood; });
    for (const auto& h : seeds) {
        if (out.size() >= m_params.max_hypotheses) break;
        if (std::all_of(out.begin(), out.end(), [&](const Hypothesis& o) { return distinct(o.pose, h.pose); }))
            out.push_back(h);
    }
    return out;
}

void HypothesisSearch::refine(const FitWindow& window, const mrpt::poses::CPose2D& odometry_now, Hypothesis& h) const {
    climbGrid(window, odometry_now, h, 2, 1);
}

void HypothesisSearch::climbGrid(const FitWindow& window, const mrpt::poses::CPose2D& odometry_now, Hypothesis& h,
                                 int levels, int moves) const {
    // 3 x 3 x 3 grids about the pose (the pose itself included), moving to the best while it is
    // better, up to `moves` times per level; the step halved at each level.
    double step_m = m_params.refine_step_m, step_rad = m_params.refine_step_rad;
    std::vector<mrpt::math::TPose2D> grid;
    std::vector<double> g;
    for (int level = 0; level < levels; ++level, step_m /= 2, step_rad /= 2)
        for (int move = 0; move < moves; ++move) {
            grid.clear();
            for (int a = -1; a <= 1; ++a)
                for (int b = -1; b <= 1; ++b)
                    for (int c = -1; c <= 1; ++c)
                        grid.push_back({h.pose.x + a * step_m, h.pose.y + b * step_m, mrpt::math::wrapToPi(h.pose.phi + c * step_rad)});
            window.scorePoses(m_map, grid, odometry_now, g);
            const std::size_t best = bestFirst(g).front();
            if (!(g[best] > h.log_likelihood)) break;
            h = {grid[best], g[best]};
        }
}

Hypothesis HypothesisSearch::climb(const FitWindow& window, const mrpt::math::TPose2D& pose,
                                   const mrpt::poses::CPose2D& odometry_now, double& own, int moves) const {
    std::vector<double> g;
    window.scorePoses(m_map, {pose}, odometry_now, g);
    own = g.front();
    Hypothesis h{pose, own};
    climbGrid(window, odometry_now, h, 3, moves);
    return h;
}

double HypothesisSearch::rivalAdvantage(const FitWindow& window, const std::vector<Hypothesis>& hypotheses,
                                        const mrpt::math::TPose2D& pose, const mrpt::poses::CPose2D& odometry_now) const {
    double best_rival = -std::numeric_limits<double>::infinity();
    for (const auto& h : hypotheses)
        if (distinct(h.pose, pose)) best_rival = std::max(best_rival, h.log_likelihood);
    if (!std::isfinite(best_rival)) return std::numeric_limits<double>::quiet_NaN();
    // The estimate refined as the rivals were, so neither side gains from the maximization alone.
    std::vector<double> own;
    window.scorePoses(m_map, {pose}, odometry_now, own);
    Hypothesis h{pose, own.front()};
    refine(window, odometry_now, h);
    return best_rival - h.log_likelihood;
}

}  // namespace simp::localization
