#include <simp/localization/ParticleSummary.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace simp::localization {
namespace {

/// Normalized linear weights of the particles (sum = 1), from their log-weights.
std::vector<double> normalizedWeights(const mrpt::poses::CPosePDFParticles& pdf) {
    const std::size_t n = pdf.size();
    std::vector<double> w(n);
    double max_lw = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) max_lw = std::max(max_lw, pdf.getW(i));
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += (w[i] = std::exp(pdf.getW(i) - max_lw));
    for (auto& x : w) x /= sum;
    return w;
}

struct WeightedMean {
    double sw = 0, sx = 0, sy = 0, sc = 0, ss = 0;
    void add(const mrpt::math::TPose2D& p, double w) {
        sw += w;
        sx += w * p.x;
        sy += w * p.y;
        sc += w * std::cos(p.phi);
        ss += w * std::sin(p.phi);
    }
    mrpt::math::TPose2D pose() const { return {sx / sw, sy / sw, std::atan2(ss, sc)}; }
};

}  // namespace

ParticleSummary summarizeParticles(const mrpt::poses::CPosePDFParticles& pdf, const ExperimentOptions& opts) {
    const std::size_t n = pdf.size();
    if (n == 0) throw std::invalid_argument("summarizeParticles: empty particle set");
    const std::vector<double> w = normalizedWeights(pdf);
    ParticleSummary s;
    s.particle_count = n;

    WeightedMean all;
    double sum_w2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        all.add(pdf.m_particles[i].d, w[i]);
        sum_w2 += w[i] * w[i];
    }
    s.ess = 1.0 / sum_w2;
    s.mean = all.pose();
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = pdf.m_particles[i].d;
        const Eigen::Vector3d d(p.x - s.mean.x, p.y - s.mean.y, mrpt::math::wrapToPi(p.phi - s.mean.phi));
        s.cov += w[i] * d * d.transpose();
    }

    if (opts.estimate_mode == EstimateMode::Mean) {
        s.estimate = s.mean;
        s.cluster_weight = 1.0;
        s.cluster_cov = s.cov;
        return s;
    }

    // Peak bin: most weight in its 3x3x3 neighbourhood (heading bins wrap around). The bins are a
    // sorted vector (one sort instead of a node per bin: this runs at every update); ties go to
    // the smallest key, as with an ordered map.
    const int nb = opts.cluster_phi_bins;
    using Key = std::tuple<long, long, int>;
    auto keyOf = [&](const mrpt::math::TPose2D& p) {
        const double u = (mrpt::math::wrapTo2Pi(p.phi)) / (2 * M_PI) * nb;
        return Key{static_cast<long>(std::floor(p.x / opts.cluster_cell_m)),
                   static_cast<long>(std::floor(p.y / opts.cluster_cell_m)), std::min(nb - 1, static_cast<int>(u))};
    };
    std::vector<Key> keys(n);
    for (std::size_t i = 0; i < n; ++i) keys[i] = keyOf(pdf.m_particles[i].d);
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b] || (keys[a] == keys[b] && a < b); });
    std::vector<std::pair<Key, double>> bins;
    for (const std::size_t i : order) {
        if (bins.empty() || bins.back().first != keys[i]) bins.emplace_back(keys[i], 0.0);
        bins.back().second += w[i];
    }
    auto binWeight = [&](const Key& k) {
        const auto it = std::lower_bound(bins.begin(), bins.end(), k,
                                         [](const std::pair<Key, double>& b, const Key& key) { return b.first < key; });
        return it != bins.end() && it->first == k ? it->second : 0.0;
    };
    Key best{};
    double best_w = -1;
    for (const auto& [k, bw] : bins) {
        (void)bw;
        double sum = 0;
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
                for (int dp = (nb >= 3 ? -1 : 0); dp <= (nb >= 3 ? 1 : 0); ++dp)
                    sum += binWeight({std::get<0>(k) + dx, std::get<1>(k) + dy, (std::get<2>(k) + dp + nb) % nb});
        if (sum > best_w) best_w = sum, best = k;
    }
    // Seed pose: weighted mean of the peak bin's neighbourhood.
    WeightedMean seed;
    for (std::size_t i = 0; i < n; ++i) {
        const Key& k = keys[i];
        const long dx = std::get<0>(k) - std::get<0>(best), dy = std::get<1>(k) - std::get<1>(best);
        const int dp = ((std::get<2>(k) - std::get<2>(best)) % nb + nb) % nb;
        if (std::abs(dx) <= 1 && std::abs(dy) <= 1 && (dp <= 1 || dp == nb - 1 || nb < 3))
            seed.add(pdf.m_particles[i].d, w[i]);
    }
    const mrpt::math::TPose2D peak = seed.pose();
    // Cluster: particles near the peak pose.
    WeightedMean cluster;
    const double r2 = opts.cluster_radius_m * opts.cluster_radius_m;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = pdf.m_particles[i].d;
        const double dx = p.x - peak.x, dy = p.y - peak.y;
        if (dx * dx + dy * dy <= r2 && std::abs(mrpt::math::wrapToPi(p.phi - peak.phi)) <= opts.cluster_max_dphi)
            cluster.add(p, w[i]);
    }
    if (cluster.sw > 0) {
        s.estimate = cluster.pose();
        s.cluster_weight = cluster.sw;
        for (std::size_t i = 0; i < n; ++i) {
            const auto& p = pdf.m_particles[i].d;
            const double dx = p.x - peak.x, dy = p.y - peak.y;
            if (dx * dx + dy * dy > r2 || std::abs(mrpt::math::wrapToPi(p.phi - peak.phi)) > opts.cluster_max_dphi)
                continue;
            const Eigen::Vector3d d(p.x - s.estimate.x, p.y - s.estimate.y, mrpt::math::wrapToPi(p.phi - s.estimate.phi));
            s.cluster_cov += (w[i] / cluster.sw) * d * d.transpose();
        }
    } else {
        s.estimate = peak;
        s.cluster_weight = seed.sw;
    }
    return s;
}

}  // namespace simp::localization
