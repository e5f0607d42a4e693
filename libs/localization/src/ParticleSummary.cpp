#include <simp/localization/ParticleSummary.h>

#include <simp/geometry/SinCos.h>
#include <simp/localization/Angle.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace simp::localization {
namespace {

/// The particles' poses and normalized linear weights (sum = 1, from the log-weights) in arrays:
/// the summary visits them in several passes, and a deque's indexing costs a division each.
void particleArrays(const mrpt::poses::CPosePDFParticles& pdf, std::vector<mrpt::math::TPose2D>& pose,
                    std::vector<double>& w) {
    const std::size_t n = pdf.m_particles.size();  // not size(): MRPT's accessors dynamic_cast per call
    pose.resize(n);
    w.resize(n);
    double max_lw = -std::numeric_limits<double>::infinity();
    std::size_t i = 0;
    for (const auto& p : pdf.m_particles) {
        pose[i] = p.d;
        w[i++] = p.log_w;
        max_lw = std::max(max_lw, p.log_w);
    }
    double sum = 0;
    for (auto& x : w) sum += (x = std::exp(x - max_lw));
    for (auto& x : w) x /= sum;
}

/// Weighted circular mean; the caller passes each particle's cos/sin of phi, computed once per summary.
struct WeightedMean {
    double sw = 0, sx = 0, sy = 0, sc = 0, ss = 0;
    void add(const mrpt::math::TPose2D& p, double cos_phi, double sin_phi, double w) {
        sw += w;
        sx += w * p.x;
        sy += w * p.y;
        sc += w * cos_phi;
        ss += w * sin_phi;
    }
    mrpt::math::TPose2D pose() const { return {sx / sw, sy / sw, std::atan2(ss, sc)}; }
};

/// Sum of w d d^T over particles, element (r, c) += (w d_r) d_c: the roundings of Eigen's
/// `w * d * d.transpose()` added to a matrix, in scalars that stay in registers (Eigen's product
/// went through a stack temporary whose reload stalled on store forwarding: 40 % of a summary).
struct Scatter {
    double m[3][3] = {};
    void add(double w, double d0, double d1, double d2) {
        const double wd[3] = {w * d0, w * d1, w * d2}, d[3] = {d0, d1, d2};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) m[r][c] += wd[r] * d[c];
    }
    Eigen::Matrix3d matrix() const {
        Eigen::Matrix3d out;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) out(r, c) = m[r][c];
        return out;
    }
};

/// The particles' bins on the cluster grid: x and y cells counted from the smallest occupied one,
/// heading bin in [0, nb).
struct ParticleBins {
    std::vector<long> x, y;
    std::vector<int> phi;
    long min_x = 0, min_y = 0, span_x = 0, span_y = 0;  ///< span: number of cells from min to max
    int nb = 1;
};

struct PeakBin {
    long x = 0, y = 0;
    int phi = 0;
};

/// Visits the 3x3x3 neighbourhood of (x, y, phi) (heading wraps around; with fewer than 3 heading bins
/// only the same heading bin) in a fixed order, so that every peak finder sums the same numbers in
/// the same order.
template <typename Weight>
double neighbourhoodWeight(const ParticleBins& b, long x, long y, int phi, const Weight& weight) {
    double sum = 0;
    for (long dx = -1; dx <= 1; ++dx)
        for (long dy = -1; dy <= 1; ++dy)
            for (int dp = (b.nb >= 3 ? -1 : 0); dp <= (b.nb >= 3 ? 1 : 0); ++dp) {
                const long u = x + dx - b.min_x, v = y + dy - b.min_y;
                if (u < 0 || v < 0 || u >= b.span_x || v >= b.span_y) continue;  // no particle there
                const int q = phi + dp;  // in [-1, nb]: wrapped without a division
                sum += weight(u, v, q < 0 ? q + b.nb : q >= b.nb ? q - b.nb : q);
            }
    return sum;
}

/// Peak on a dense array over the occupied cells' bounding box (the usual case: a few thousand bins);
/// the array is visited in (x, y, phi) order, the order of the sorted bins below.
PeakBin peakOnDenseGrid(const ParticleBins& b, const std::vector<double>& w) {
    const auto index = [&](long u, long v, int phi) {
        return (static_cast<std::size_t>(u) * static_cast<std::size_t>(b.span_y) + static_cast<std::size_t>(v)) *
                   static_cast<std::size_t>(b.nb) + static_cast<std::size_t>(phi);
    };
    std::vector<double> grid(static_cast<std::size_t>(b.span_x * b.span_y) * static_cast<std::size_t>(b.nb), 0.0);
    std::vector<std::uint8_t> occupied(grid.size(), 0);
    for (std::size_t i = 0; i < w.size(); ++i) {
        const std::size_t k = index(b.x[i] - b.min_x, b.y[i] - b.min_y, b.phi[i]);
        grid[k] += w[i];  // index order, as the sorted bins sum
        occupied[k] = 1;
    }
    const auto weight = [&](long u, long v, int phi) { return grid[index(u, v, phi)]; };
    PeakBin best;
    double best_w = -1;
    for (long u = 0; u < b.span_x; ++u)
        for (long v = 0; v < b.span_y; ++v)
            for (int phi = 0; phi < b.nb; ++phi) {
                if (!occupied[index(u, v, phi)]) continue;
                const double sum = neighbourhoodWeight(b, b.min_x + u, b.min_y + v, phi, weight);
                if (sum > best_w) best_w = sum, best = {b.min_x + u, b.min_y + v, phi};
            }
    return best;
}

/// Peak over a sorted vector of occupied bins (particles spread over a bounding box too large for an
/// array): keys packed in one integer whose order is that of (x, y, phi), 27 bits per cell index.
PeakBin peakOnSortedBins(const ParticleBins& b, const std::vector<double>& w) {
    constexpr int kPhiBits = 9, kCellBits = 27;  // cluster_phi_bins <= 360
    const auto pack = [&](long u, long v, int phi) {
        return (static_cast<std::uint64_t>(u) << (kCellBits + kPhiBits)) | (static_cast<std::uint64_t>(v) << kPhiBits) |
               static_cast<std::uint64_t>(phi);
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order(w.size());  // (bin, particle): ties by index
    for (std::size_t i = 0; i < w.size(); ++i)
        order[i] = {pack(b.x[i] - b.min_x, b.y[i] - b.min_y, b.phi[i]), static_cast<std::uint32_t>(i)};
    std::sort(order.begin(), order.end());
    std::vector<std::pair<std::uint64_t, double>> bins;
    for (const auto& [key, i] : order) {
        if (bins.empty() || bins.back().first != key) bins.emplace_back(key, 0.0);
        bins.back().second += w[i];
    }
    const auto weight = [&](long u, long v, int phi) {
        const std::uint64_t k = pack(u, v, phi);
        const auto it = std::lower_bound(bins.begin(), bins.end(), k,
                                         [](const std::pair<std::uint64_t, double>& e, std::uint64_t key) { return e.first < key; });
        return it != bins.end() && it->first == k ? it->second : 0.0;
    };
    PeakBin best;
    double best_w = -1;
    for (const auto& [k, bw] : bins) {
        (void)bw;
        const long x = b.min_x + static_cast<long>(k >> (kCellBits + kPhiBits));
        const long y = b.min_y + static_cast<long>((k >> kPhiBits) & ((1UL << kCellBits) - 1));
        const int phi = static_cast<int>(k & ((1U << kPhiBits) - 1));
        const double sum = neighbourhoodWeight(b, x, y, phi, weight);
        if (sum > best_w) best_w = sum, best = {x, y, phi};
    }
    return best;
}

}  // namespace

ParticleSummary summarizeParticles(const mrpt::poses::CPosePDFParticles& pdf, const ExperimentOptions& opts) {
    const std::size_t n = pdf.m_particles.size();  // not size(): MRPT's accessors dynamic_cast per call
    if (n == 0) throw std::invalid_argument("summarizeParticles: empty particle set");
    std::vector<mrpt::math::TPose2D> pose;
    std::vector<double> w;
    particleArrays(pdf, pose, w);
    ParticleSummary s;
    s.particle_count = n;

    std::vector<double> cos_phi(n), sin_phi(n);
    for (std::size_t i = 0; i < n; ++i) geometry::sinCos(pose[i].phi, sin_phi[i], cos_phi[i]);
    WeightedMean all;
    double sum_w2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        all.add(pose[i], cos_phi[i], sin_phi[i], w[i]);
        sum_w2 += w[i] * w[i];
    }
    s.ess = 1.0 / sum_w2;
    s.mean = all.pose();
    Scatter cov;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = pose[i];
        cov.add(w[i], p.x - s.mean.x, p.y - s.mean.y, wrapToPi(p.phi - s.mean.phi));
    }
    s.cov = cov.matrix();

    if (opts.estimate_mode == EstimateMode::Mean) {
        s.estimate = s.mean;
        s.cluster_weight = 1.0;
        s.cluster_cov = s.cov;
        return s;
    }

    // Peak bin: most weight in its 3x3x3 neighbourhood (heading bins wrap around); a bin's weight sums
    // its particles in index order; ties go to the smallest (x, y, phi). This runs at every update:
    // a dense array when the particles' bounding box is small, else sorted packed keys (same result).
    ParticleBins b;
    b.nb = opts.cluster_phi_bins;
    b.x.resize(n);
    b.y.resize(n);
    b.phi.resize(n);
    b.min_x = b.min_y = std::numeric_limits<long>::max();
    long max_x = std::numeric_limits<long>::min(), max_y = std::numeric_limits<long>::min();
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = pose[i];
        const double u = (wrapTo2Pi(p.phi)) / (2 * M_PI) * b.nb;
        const double fx = std::floor(p.x / opts.cluster_cell_m), fy = std::floor(p.y / opts.cluster_cell_m);
        if (!(std::abs(fx) < 1e15 && std::abs(fy) < 1e15))
            throw std::runtime_error("summarizeParticles: particle " + std::to_string(i) + " at (" + std::to_string(p.x) +
                                     ", " + std::to_string(p.y) + ") m is not a finite place on the cluster grid");
        b.x[i] = static_cast<long>(fx);
        b.y[i] = static_cast<long>(fy);
        b.phi[i] = std::min(b.nb - 1, static_cast<int>(u));
        b.min_x = std::min(b.min_x, b.x[i]);
        b.min_y = std::min(b.min_y, b.y[i]);
        max_x = std::max(max_x, b.x[i]);
        max_y = std::max(max_y, b.y[i]);
    }
    b.span_x = max_x - b.min_x + 1;
    b.span_y = max_y - b.min_y + 1;
    if (b.span_x > (1L << 27) || b.span_y > (1L << 27))
        throw std::runtime_error("summarizeParticles: the particles span more than 2^27 cells of cluster_cell_m = " +
                                 std::to_string(opts.cluster_cell_m) + " m");
    const double dense_cells = static_cast<double>(b.span_x) * static_cast<double>(b.span_y) * b.nb;
    const PeakBin best = dense_cells <= std::max(16.0 * static_cast<double>(n), 65536.0) ? peakOnDenseGrid(b, w)
                                                                                          : peakOnSortedBins(b, w);
    // Seed pose: weighted mean of the peak bin's neighbourhood.
    WeightedMean seed;
    for (std::size_t i = 0; i < n; ++i) {
        const long dx = b.x[i] - best.x, dy = b.y[i] - best.y;
        const int dphi = b.phi[i] - best.phi;  // in (-nb, nb): its residue mod nb without a division
        const int dp = dphi < 0 ? dphi + b.nb : dphi;
        if (std::abs(dx) <= 1 && std::abs(dy) <= 1 && (dp <= 1 || dp == b.nb - 1 || b.nb < 3))
            seed.add(pose[i], cos_phi[i], sin_phi[i], w[i]);
    }
    const mrpt::math::TPose2D peak = seed.pose();
    // Cluster: particles near the peak pose.
    WeightedMean cluster;
    const double r2 = opts.cluster_radius_m * opts.cluster_radius_m;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = pose[i];
        const double dx = p.x - peak.x, dy = p.y - peak.y;
        if (dx * dx + dy * dy <= r2 && std::abs(wrapToPi(p.phi - peak.phi)) <= opts.cluster_max_dphi)
            cluster.add(p, cos_phi[i], sin_phi[i], w[i]);
    }
    if (cluster.sw > 0) {
        s.estimate = cluster.pose();
        s.cluster_weight = cluster.sw;
        Scatter cluster_cov;
        for (std::size_t i = 0; i < n; ++i) {
            const auto& p = pose[i];
            const double dx = p.x - peak.x, dy = p.y - peak.y;
            if (dx * dx + dy * dy > r2 || std::abs(wrapToPi(p.phi - peak.phi)) > opts.cluster_max_dphi)
                continue;
            cluster_cov.add(w[i] / cluster.sw, p.x - s.estimate.x, p.y - s.estimate.y, wrapToPi(p.phi - s.estimate.phi));
        }
        s.cluster_cov = cluster_cov.matrix();
    } else {
        s.estimate = peak;
        s.cluster_weight = seed.sw;
    }
    return s;
}

}  // namespace simp::localization
