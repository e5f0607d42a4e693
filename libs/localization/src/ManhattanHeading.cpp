#include <simp/localization/ManhattanHeading.h>

#include <simp/geometry/Box3D.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace simp::localization {
namespace {

constexpr double kQuarter = 0.5 * M_PI;

/// a wrapped to [-pi/4, pi/4]: its distance to the nearest of the axes 0 + k pi/2.
double wrapQuarter(double a) { return a - kQuarter * std::round(a / kQuarter); }

/// a wrapped to [0, pi/2) as a position in a table of `bins` bins over the period: bin and fraction.
struct QuarterBin {
    std::size_t bin;
    double fraction;
};
QuarterBin quarterBin(double a, std::size_t bins) {
    double t = (a - kQuarter * std::floor(a / kQuarter)) * (static_cast<double>(bins) / kQuarter);
    t = std::clamp(t, 0.0, static_cast<double>(bins) - 1e-9);
    const auto bin = static_cast<std::size_t>(t);
    return {bin, t - static_cast<double>(bin)};
}

}  // namespace

const io::OptionTable<ManhattanHeadingOptions>& ManhattanHeadingOptions::table() {
    using O = ManhattanHeadingOptions;
    using io::ValueRange;
    static const io::OptionTable<O> t =
        io::OptionTable<O>("ManhattanHeading")
            .number("weight", &O::weight, "", ValueRange::between(0, 100),
                    "exponent of a frame's box-yaw heading likelihood (mean over its detections), relative to Eq. singw's 1 (0 = off)")
            .number("yaw_sigma_rad", &O::yaw_sigma_rad, "rad", ValueRange::aboveUpTo(0, 1), "std of a detected box's yaw")
            .number("aligned_tolerance_rad", &O::aligned_tolerance_rad, "rad", ValueRange::aboveUpTo(0, M_PI / 4),
                    "a map object this close to the map's axes is square to them")
            .number("min_aligned_fraction", &O::min_aligned_fraction, "", ValueRange::fraction(),
                    "the model is used only when this share of the map's objects is square to its axes")
            .number("outlier_fraction", &O::outlier_fraction, "", ValueRange::between(0, 0.999),
                    "share of the detections of a square class assumed not square (moved, turned, false)")
            .number("consensus_tolerance_rad", &O::consensus_tolerance_rad, "rad", ValueRange::between(0, M_PI / 4),
                    "a detection votes only when its object's yaw agrees this well with the other objects' (0 = off)")
            .number("consensus_window_s", &O::consensus_window_s, "s", ValueRange::aboveUpTo(0, 3600),
                    "the other objects: those seen in the last this many seconds")
            .integer("consensus_min_tracks", &O::consensus_min_tracks, ValueRange::between(1, 1000),
                     "at least this many other objects, else the detection does not vote")
            .integer("consensus_min_detections", &O::consensus_min_detections, ValueRange::between(1, 1000000),
                     "only objects detected this many times vote or count among the others");
    return t;
}

void ManhattanHeadingOptions::loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    table().load(cfg, s, *this);
}

ManhattanHeading::ManhattanHeading(const maps::CObjectMap& map, const ManhattanHeadingOptions& options)
    : m_map(map), m_opts(options) {
    const auto& data = map.data();
    m_inlier_weight.assign(data.class_names.size(), 0.0);
    if (data.objects.empty()) return;
    // The axes: the mean of 4 x yaw (a box's yaw is known modulo 90 deg), footprints weighing by area.
    double sx = 0.0, sy = 0.0;
    for (const auto& o : data.objects) {
        const double a = o.box.size.x() * o.box.size.y(), yaw = geometry::yawOf(o.box);
        sx += a * std::cos(4.0 * yaw);
        sy += a * std::sin(4.0 * yaw);
    }
    m_axis_rad = std::atan2(sy, sx) / 4.0;
    if (m_axis_rad < 0) m_axis_rad += kQuarter;
    std::vector<std::size_t> count(data.class_names.size(), 0), aligned(data.class_names.size(), 0);
    std::size_t n_aligned = 0;
    for (const auto& o : data.objects) {
        const bool square = std::abs(wrapQuarter(geometry::yawOf(o.box) - m_axis_rad)) <= m_opts.aligned_tolerance_rad;
        n_aligned += square ? 1 : 0;
        if (o.class_id < 0 || static_cast<std::size_t>(o.class_id) >= count.size()) continue;
        ++count[static_cast<std::size_t>(o.class_id)];
        aligned[static_cast<std::size_t>(o.class_id)] += square ? 1 : 0;
    }
    m_aligned_fraction = static_cast<double>(n_aligned) / static_cast<double>(data.objects.size());
    for (std::size_t c = 0; c < count.size(); ++c)
        if (count[c] > 0)
            m_inlier_weight[c] = (1.0 - m_opts.outlier_fraction) * static_cast<double>(aligned[c]) / static_cast<double>(count[c]);
    m_active = m_opts.weight > 0.0 && m_aligned_fraction >= m_opts.min_aligned_fraction;
    // log p(psi | phi) depends on the residual r = phi + psi - alpha alone: tabulated per class over
    // one period, so that an update's table is a sum of shifted copies (no exp or log per update).
    m_residual_log.assign(m_inlier_weight.size(), {});
    for (std::size_t c = 0; c < m_inlier_weight.size(); ++c) {
        if (m_inlier_weight[c] <= 0.0) continue;
        m_residual_log[c].resize(kBins);
        for (std::size_t j = 0; j < kBins; ++j)
            m_residual_log[c][j] = detectionLogLikelihood(static_cast<int>(c), m_axis_rad, kQuarter * static_cast<double>(j) / kBins);
    }
}

double ManhattanHeading::inlierWeight(int cls) const {
    return cls >= 0 && static_cast<std::size_t>(cls) < m_inlier_weight.size() ? m_inlier_weight[static_cast<std::size_t>(cls)] : 0.0;
}

int ManhattanHeading::squareClassOf(const simp::obs::CObservationObjects3D& obs, std::size_t k) const {
    const int cls = m_map.usableClassOf(obs, k);
    return inlierWeight(cls) > 0.0 ? cls : -1;
}

double ManhattanHeading::detectionLogLikelihood(int cls, double psi_robot_rad, double phi_rad) const {
    const double w = inlierWeight(cls), s = m_opts.yaw_sigma_rad;
    const double r = wrapQuarter(phi_rad + psi_robot_rad - m_axis_rad);
    const double gauss = std::exp(-0.5 * r * r / (s * s)) / (s * std::sqrt(2.0 * M_PI));
    return std::log(w * gauss + (1.0 - w) / kQuarter);
}

std::size_t ManhattanHeading::addGroup(const std::vector<const WeightedObservation*>& group,
                                       const mrpt::math::TPose2D* poses, std::size_t n, double* out_log) const {
    struct Used {
        int cls;
        double psi, weight;
    };
    std::vector<Used> used;
    double sum_weight = 0.0;
    for (const auto* o : group)
        for (std::size_t k = 0; k < o->obs->size(); ++k) {
            const auto& weights = o->heading_weights.empty() ? o->weights : o->heading_weights;
            const double wk = weights.empty() ? 1.0 : weights.at(k);
            if (wk <= 0.0) continue;
            const int cls = m_map.usableClassOf(*o->obs, k);
            if (inlierWeight(cls) <= 0.0) continue;
            used.push_back({cls, geometry::yawOf(o->obs->boxInRobot(k)), wk});
            sum_weight += wk;
        }
    if (used.empty()) return 0;
    // The sum depends on phi modulo 90 deg only: tabulated at phi_j = j x 90 deg / kBins, where
    // detection k's residual is phi_j + psi_k - alpha, i.e. its class table shifted by (psi_k - alpha).
    std::array<double, kBins + 1> table{};
    for (const auto& u : used) {
        const auto& residual_log = m_residual_log[static_cast<std::size_t>(u.cls)];
        const auto [m, f] = quarterBin(u.psi - m_axis_rad, kBins);
        for (std::size_t j = 0; j < kBins; ++j) {
            const std::size_t i0 = (j + m) % kBins, i1 = (i0 + 1) % kBins;
            table[j] += u.weight * ((1.0 - f) * residual_log[i0] + f * residual_log[i1]);
        }
    }
    const double factor = m_opts.weight / sum_weight;  // the weighted mean
    for (std::size_t j = 0; j < kBins; ++j) table[j] *= factor;
    table[kBins] = table[0];
    for (std::size_t i = 0; i < n; ++i) {
        const auto [j, f] = quarterBin(poses[i].phi, kBins);
        out_log[i] += (1.0 - f) * table[j] + f * table[j + 1];
    }
    return used.size();
}

std::size_t ManhattanHeading::addLogLikelihoods(const std::vector<WeightedObservation>& observations, bool per_frame,
                                                const mrpt::math::TPose2D* poses, std::size_t n, double* out_log) const {
    if (!m_active) return 0;
    std::size_t used = 0;
    for (const auto& group : frameGroups(observations, per_frame)) used += addGroup(group, poses, n, out_log);
    return used;
}

}  // namespace simp::localization
