#include <simp/localization/LocalizeOptions.h>
#include <simp/io/StrictNumber.h>
#include <simp/localization/Localizer.h>

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace simp::localization {
namespace {

constexpr const char* kExperiment = "LocalizationExperiment";
constexpr const char* kMotion = "MotionModel";

std::string where(const std::string& section, const std::string& key) { return "[" + section + "] " + key; }

/// Strictly parsed number: the whole value must be a finite number.
double readNumber(const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
                  double def) {
    // Read before the presence test: io::StrictIni learns the key as known from the read.
    const std::string text = cfg.read_string(section, key, "");
    if (!cfg.keyExists(section, key)) return def;
    const auto v = io::parseFiniteNumber(text);
    if (!v) throw std::invalid_argument(where(section, key) + " = '" + text + "' is not a finite number");
    return *v;
}

double readPositive(const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
                    double def, bool allow_zero) {
    const double v = readNumber(cfg, section, key, def);
    if (v < 0 || (!allow_zero && v == 0))
        throw std::invalid_argument(where(section, key) + " must be " + (allow_zero ? ">= 0" : "> 0"));
    return v;
}

bool readBool(const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key, bool def) {
    std::string t = cfg.read_string(section, key, "");  // read first: see readNumber
    if (!cfg.keyExists(section, key)) return def;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (t == "true" || t == "1" || t == "yes") return true;
    if (t == "false" || t == "0" || t == "no") return false;
    throw std::invalid_argument(where(section, key) + " = '" + t + "' is not a boolean (true/false)");
}

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

}  // namespace

const std::vector<std::string>& sensorModelNames() {
    static const std::vector<std::string> names{"simp", "edt", "d", "o", "lidar", "simp+lidar"};
    return names;
}

void ExperimentOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    const double n = readPositive(cfg, s, "particles_count", static_cast<double>(particles_count), false);
    if (n != std::floor(n)) throw std::invalid_argument(where(s, "particles_count") + " must be an integer");
    particles_count = static_cast<std::size_t>(n);
    const double sd = readPositive(cfg, s, "seed", seed, true);
    if (sd != std::floor(sd) || sd > 4294967295.0)
        throw std::invalid_argument(where(s, "seed") + " must be an integer in [0, 2^32)");
    seed = static_cast<std::uint32_t>(sd);
    sensor_model = cfg.read_string(s, "sensor_model", sensor_model);
    if (!sensor_model.empty() &&
        std::find(sensorModelNames().begin(), sensorModelNames().end(), sensor_model) == sensorModelNames().end())
        throw std::invalid_argument(where(s, "sensor_model") + " = '" + sensor_model + "' is not one of " +
                                    joined(sensorModelNames()));
    free_cells_threshold = readNumber(cfg, s, "free_cells_threshold", free_cells_threshold);
    if (!(free_cells_threshold > 0 && free_cells_threshold <= 1))
        throw std::invalid_argument(where(s, "free_cells_threshold") + " must be in (0, 1]");
    prune_outside_free_space = readBool(cfg, s, "prune_outside_free_space", prune_outside_free_space);
    update_min_d_xy = readPositive(cfg, s, "update_min_d_xy", update_min_d_xy, true);
    update_min_d_phi = readPositive(cfg, s, "update_min_d_phi", update_min_d_phi, true);
    keep_skipped_detections = readBool(cfg, s, "keep_skipped_detections", keep_skipped_detections);
    prune_keeps_weight = readBool(cfg, s, "prune_keeps_weight", prune_keeps_weight);
    singw_per_frame = readBool(cfg, s, "singw_per_frame", singw_per_frame);
    recovery_alpha_slow = readPositive(cfg, s, "recovery_alpha_slow", recovery_alpha_slow, true);
    recovery_alpha_fast = readPositive(cfg, s, "recovery_alpha_fast", recovery_alpha_fast, true);
    if (recovery_alpha_slow > 1.0 || recovery_alpha_fast > 1.0)
        throw std::invalid_argument(where(s, "recovery_alpha_slow") + " and recovery_alpha_fast must be in [0, 1]");
    if (recovery_alpha_fast > 0.0 && !(recovery_alpha_slow < recovery_alpha_fast))
        throw std::invalid_argument(where(s, "recovery_alpha_slow") + " = " + std::to_string(recovery_alpha_slow) +
                                    " must be smaller than recovery_alpha_fast = " + std::to_string(recovery_alpha_fast));
    const std::string mode = cfg.read_string(s, "estimate_mode", estimate_mode == EstimateMode::Cluster ? "cluster" : "mean");
    if (mode == "cluster")
        estimate_mode = EstimateMode::Cluster;
    else if (mode == "mean")
        estimate_mode = EstimateMode::Mean;
    else
        throw std::invalid_argument(where(s, "estimate_mode") + " = '" + mode + "' is not one of cluster, mean");
    cluster_radius_m = readPositive(cfg, s, "cluster_radius_m", cluster_radius_m, false);
    cluster_max_dphi = readPositive(cfg, s, "cluster_max_dphi", cluster_max_dphi, false);
    cluster_cell_m = readPositive(cfg, s, "cluster_cell_m", cluster_cell_m, false);
    const double bins = readPositive(cfg, s, "cluster_phi_bins", cluster_phi_bins, false);
    if (bins != std::floor(bins) || bins > 360)
        throw std::invalid_argument(where(s, "cluster_phi_bins") + " must be an integer in [1, 360]");
    cluster_phi_bins = static_cast<int>(bins);
    const double tmin = readPositive(cfg, s, "tracking_min_particles", static_cast<double>(tracking_min_particles), true);
    if (tmin != std::floor(tmin) || tmin > 1e7)
        throw std::invalid_argument(where(s, "tracking_min_particles") + " must be an integer in [0, 1e7]");
    tracking_min_particles = static_cast<std::size_t>(tmin);
    min_spread_xy_m = readPositive(cfg, s, "min_spread_xy_m", min_spread_xy_m, true);
    min_spread_phi_rad = readPositive(cfg, s, "min_spread_phi_rad", min_spread_phi_rad, true);
    if (min_spread_xy_m > 5.0) throw std::invalid_argument(where(s, "min_spread_xy_m") + " must be in [0, 5] m");
    if (min_spread_phi_rad > M_PI) throw std::invalid_argument(where(s, "min_spread_phi_rad") + " must be in [0, pi] rad");
    const std::string from = cfg.read_string(s, "report_from", report_from == ReportFrom::Localized ? "localized" : "start");
    if (from == "localized")
        report_from = ReportFrom::Localized;
    else if (from == "start")
        report_from = ReportFrom::Start;
    else
        throw std::invalid_argument(where(s, "report_from") + " = '" + from + "' is not one of localized, start");
    write_particles = readBool(cfg, s, "write_particles", write_particles);
    write_png = readBool(cfg, s, "write_png", write_png);
}

void ExperimentOptions::dumpToTextStream(std::ostream& out) const {
    out << "[" << kExperiment << "]\n"
        << "particles_count          = " << particles_count << "\n"
        << "seed                     = " << seed << "\n"
        << "sensor_model             = " << (sensor_model.empty() ? "(object map's)" : sensor_model) << "\n"
        << "free_cells_threshold     = " << free_cells_threshold << "\n"
        << "prune_outside_free_space = " << (prune_outside_free_space ? "true" : "false") << "\n"
        << "update_min_d_xy (m)      = " << update_min_d_xy << "\n"
        << "update_min_d_phi (rad)   = " << update_min_d_phi << "\n"
        << "keep_skipped_detections  = " << (keep_skipped_detections ? "true" : "false") << "\n"
        << "prune_keeps_weight       = " << (prune_keeps_weight ? "true" : "false") << "\n"
        << "singw_per_frame          = " << (singw_per_frame ? "true" : "false") << "\n"
        << "recovery_alpha_slow      = " << recovery_alpha_slow << "\n"
        << "recovery_alpha_fast      = " << recovery_alpha_fast << "\n"
        << "estimate_mode            = " << (estimate_mode == EstimateMode::Cluster ? "cluster" : "mean") << "\n"
        << "cluster_radius_m         = " << cluster_radius_m << "\n"
        << "cluster_max_dphi (rad)   = " << cluster_max_dphi << "\n"
        << "cluster_cell_m           = " << cluster_cell_m << "\n"
        << "cluster_phi_bins         = " << cluster_phi_bins << "\n"
        << "tracking_min_particles   = " << tracking_min_particles << "\n"
        << "min_spread_xy_m          = " << min_spread_xy_m << "\n"
        << "min_spread_phi_rad       = " << min_spread_phi_rad << "\n"
        << "report_from              = " << (report_from == ReportFrom::Localized ? "localized" : "start") << "\n";
}

namespace {
double readFraction(const mrpt::config::CConfigFileBase& cfg, const std::string& s, const std::string& key, double def) {
    const double v = readNumber(cfg, s, key, def);
    if (v < 0 || v > 1) throw std::invalid_argument(where(s, key) + " = " + std::to_string(v) + " must be in [0, 1]");
    return v;
}
std::size_t readCount(const mrpt::config::CConfigFileBase& cfg, const std::string& s, const std::string& key,
                      std::size_t def) {
    const double v = readPositive(cfg, s, key, static_cast<double>(def), false);
    if (v != std::floor(v) || v > 1e6) throw std::invalid_argument(where(s, key) + " must be an integer in [1, 1e6]");
    return static_cast<std::size_t>(v);
}
}  // namespace

void loadStateParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, StateParams& p) {
    p.fit_window = readCount(cfg, s, "fit_window", p.fit_window);
    p.fit_max_age_s = readPositive(cfg, s, "fit_max_age_s", p.fit_max_age_s, false);
    p.fit_min_detections = readCount(cfg, s, "fit_min_detections", p.fit_min_detections);
    if (p.fit_min_detections > p.fit_window)
        throw std::invalid_argument(where(s, "fit_min_detections") + " must be <= fit_window");
    p.explained_ratio = readPositive(cfg, s, "explained_ratio", p.explained_ratio, false);
    p.localized_min_fit = readFraction(cfg, s, "localized_min_fit", p.localized_min_fit);
    p.localized_min_weight = readFraction(cfg, s, "localized_min_weight", p.localized_min_weight);
    p.localized_max_std_m = readPositive(cfg, s, "localized_max_std_m", p.localized_max_std_m, false);
    p.localized_min_updates = readCount(cfg, s, "localized_min_updates", p.localized_min_updates);
    p.lost_window = readCount(cfg, s, "lost_window", p.lost_window);
    if (p.lost_window > p.fit_window) throw std::invalid_argument(where(s, "lost_window") + " must be <= fit_window");
    p.lost_max_fit = readFraction(cfg, s, "lost_max_fit", p.lost_max_fit);
    p.lost_min_weight = readFraction(cfg, s, "lost_min_weight", p.lost_min_weight);
    p.rival_margin = readPositive(cfg, s, "rival_margin", p.rival_margin, true);
    p.rival_lost_margin = readPositive(cfg, s, "rival_lost_margin", p.rival_lost_margin, false);
    p.object_radius_m = readPositive(cfg, s, "object_radius_m", p.object_radius_m, true);
    if (p.lost_max_fit >= p.localized_min_fit)
        throw std::invalid_argument(where(s, "lost_max_fit") + " must be smaller than localized_min_fit");
}

void loadNoveltyParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, DetectionNoveltyParams& p) {
    p.decorrelation_distance_m = readPositive(cfg, s, "decorrelation_distance_m", p.decorrelation_distance_m, true);
    p.min_weight = readFraction(cfg, s, "min_weight", p.min_weight);
    if (!(p.min_weight > 0)) throw std::invalid_argument(where(s, "min_weight") + " must be in (0, 1]");
    p.track_radius_m = readPositive(cfg, s, "track_radius_m", p.track_radius_m, false);
    p.track_timeout_s = readPositive(cfg, s, "track_timeout_s", p.track_timeout_s, false);
}

void loadResettingParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, SensorResettingParams& p) {
    p.global_fraction = readFraction(cfg, s, "global_fraction", p.global_fraction);
    p.lost_fraction = readFraction(cfg, s, "lost_fraction", p.lost_fraction);
    p.localized_fraction = readFraction(cfg, s, "localized_fraction", p.localized_fraction);
    p.uniform_share = readFraction(cfg, s, "uniform_share", p.uniform_share);
    p.sampler.position_std_m = readPositive(cfg, s, "position_std_m", p.sampler.position_std_m, true);
    p.sampler.heading_std_rad = readPositive(cfg, s, "heading_std_rad", p.sampler.heading_std_rad, true);
    p.sampler.square_ratio = readFraction(cfg, s, "square_ratio", p.sampler.square_ratio);
}

void loadSearchParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, HypothesisSearchParams& p) {
    p.enabled = readBool(cfg, s, "enabled", p.enabled);
    p.min_window_detections = readCount(cfg, s, "min_window_detections", p.min_window_detections);
    p.max_candidates = readCount(cfg, s, "max_candidates", p.max_candidates);
    p.refine_top = readCount(cfg, s, "refine_top", p.refine_top);
    p.refine_step_m = readPositive(cfg, s, "refine_step_m", p.refine_step_m, false);
    p.refine_step_rad = readPositive(cfg, s, "refine_step_rad", p.refine_step_rad, false);
    p.distinct_distance_m = readPositive(cfg, s, "distinct_distance_m", p.distinct_distance_m, false);
    p.distinct_heading_rad = readPositive(cfg, s, "distinct_heading_rad", p.distinct_heading_rad, false);
    p.max_hypotheses = readCount(cfg, s, "max_hypotheses", p.max_hypotheses);
    p.while_global = readBool(cfg, s, "while_global", p.while_global);
    p.while_localized = readBool(cfg, s, "while_localized", p.while_localized);
    p.check_period_s = readPositive(cfg, s, "check_period_s", p.check_period_s, true);
}

void loadChallengerParams(const mrpt::config::CConfigFileBase& cfg, const std::string& s, ChallengerParams& p) {
    p.enabled = readBool(cfg, s, "enabled", p.enabled);
    p.win_margin = readPositive(cfg, s, "win_margin", p.win_margin, true);
    p.agree_distance_m = readPositive(cfg, s, "agree_distance_m", p.agree_distance_m, true);
    p.reset_fraction = readFraction(cfg, s, "reset_fraction", p.reset_fraction);
    const double n = readPositive(cfg, s, "particles", static_cast<double>(p.particles), true);
    if (n != std::floor(n) || n > 1e6) throw std::invalid_argument(where(s, "particles") + " must be an integer in [0, 1e6]");
    p.particles = static_cast<std::size_t>(n);
}

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions MotionModelOptions::paperDefaults() {
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions o;
    o.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
    // sigma_odom = (0.15, 0.15, 0.15): std of translation 0.15 m per metre travelled, of rotation
    // 0.15 rad per radian turned (the authors' MixedFSR scales the noise by the motion).
    o.gaussianModel.a1 = 0.15;   // m / m
    o.gaussianModel.a2 = 0.0;    // m / rad
    o.gaussianModel.a3 = 0.0;    // rad / m
    o.gaussianModel.a4 = 0.15;   // rad / rad
    o.gaussianModel.minStdXY = 0.01;   // m
    o.gaussianModel.minStdPHI = 0.01;  // rad
    return o;
}

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions MotionModelOptions::defaults() {
    auto o = paperDefaults();
    // The Thrun model's knobs (unused by the gaussian model) as the .ini files write MRPT's
    // defaults, so that no field differs between the defaults and config_ini/simp.ini.
    auto& t = o.thrunModel;
    t.nParticlesCount = 300;
    t.alfa1_rot_rot = static_cast<float>(0.05);
    t.alfa2_rot_trans = static_cast<float>(0.0698);
    t.alfa3_trans_trans = static_cast<float>(0.01);
    t.alfa4_trans_rot = static_cast<float>(0.0057);
    t.additional_std_XY = static_cast<float>(0.001);
    t.additional_std_phi = static_cast<float>(0.00087);
    o.gaussianModel.a1 = 0.05;  // m / m
    o.gaussianModel.a4 = 0.05;  // rad / rad
    return o;
}

void MotionModelOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& s) {
    using M = mrpt::obs::CActionRobotMovement2D;
    auto& o = mrpt_options;
    const std::string model = cfg.read_string(s, "modelSelection", o.modelSelection == M::mmGaussian ? "gaussian" : "thrun");
    if (model == "gaussian")
        o.modelSelection = M::mmGaussian;
    else if (model == "thrun")
        o.modelSelection = M::mmThrun;
    else
        throw std::invalid_argument(where(s, "modelSelection") + " = '" + model + "' is not one of gaussian, thrun");
    auto& g = o.gaussianModel;
    g.a1 = readPositive(cfg, s, "a1", g.a1, true);
    g.a2 = readPositive(cfg, s, "a2", g.a2, true);
    g.a3 = readPositive(cfg, s, "a3", g.a3, true);
    g.a4 = readPositive(cfg, s, "a4", g.a4, true);
    g.minStdXY = readPositive(cfg, s, "minStdXY", g.minStdXY, true);
    g.minStdPHI = readPositive(cfg, s, "minStdPHI", g.minStdPHI, true);
    auto& t = o.thrunModel;
    const double np = readPositive(cfg, s, "nParticlesCount", t.nParticlesCount, false);
    t.nParticlesCount = static_cast<std::uint32_t>(np);
    t.alfa1_rot_rot = static_cast<float>(readPositive(cfg, s, "alfa1_rot_rot", t.alfa1_rot_rot, true));
    t.alfa2_rot_trans = static_cast<float>(readPositive(cfg, s, "alfa2_rot_trans", t.alfa2_rot_trans, true));
    t.alfa3_trans_trans = static_cast<float>(readPositive(cfg, s, "alfa3_trans_trans", t.alfa3_trans_trans, true));
    t.alfa4_trans_rot = static_cast<float>(readPositive(cfg, s, "alfa4_trans_rot", t.alfa4_trans_rot, true));
    t.additional_std_XY = static_cast<float>(readPositive(cfg, s, "additional_std_XY", t.additional_std_XY, true));
    t.additional_std_phi = static_cast<float>(readPositive(cfg, s, "additional_std_phi", t.additional_std_phi, true));
}

void MotionModelOptions::dumpToTextStream(std::ostream& out) const {
    const auto& o = mrpt_options;
    out << "[" << kMotion << "]\n"
        << "modelSelection = " << (o.modelSelection == mrpt::obs::CActionRobotMovement2D::mmGaussian ? "gaussian" : "thrun")
        << "\n"
        << "a1 (m/m) = " << o.gaussianModel.a1 << ", a2 (m/rad) = " << o.gaussianModel.a2
        << ", a3 (rad/m) = " << o.gaussianModel.a3 << ", a4 (rad/rad) = " << o.gaussianModel.a4 << "\n"
        << "minStdXY (m) = " << o.gaussianModel.minStdXY << ", minStdPHI (rad) = " << o.gaussianModel.minStdPHI << "\n";
}

std::vector<std::string> reconcilePfOptions(mrpt::bayes::CParticleFilter::TParticleFilterOptions& pf) {
    std::vector<std::string> notes;
    using PF = mrpt::bayes::CParticleFilter;
    // MRPT 2.5's KLD-sampling prediction (CMonteCarloLocalization2D, pfStandardProposal) throws
    // "resamplingMethod must be 'prMultinomial'" for any other method.
    if (pf.adaptiveSampleSize && pf.resamplingMethod != PF::prMultinomial) {
        notes.push_back("[PF_options] adaptiveSampleSize = true (KLD sampling): resamplingMethod set to prMultinomial "
                        "(MRPT's KLD sampling supports no other)");
        pf.resamplingMethod = PF::prMultinomial;
    }
    return notes;
}

void loadLocalizerOptions(const mrpt::config::CConfigFileBase& cfg, LocalizerOptions& options) {
    options.experiment.loadFromConfigFile(cfg, kExperiment);
    options.motion.loadFromConfigFile(cfg, kMotion);
    if (cfg.sectionExists("PF_options")) options.pf.loadFromConfigFile(cfg, "PF_options");
    options.kld.loadFromConfigFile(cfg, "KLD_options");
    loadStateParams(cfg, "State", options.state);
    loadNoveltyParams(cfg, "DetectionNovelty", options.novelty);
    loadResettingParams(cfg, "SensorResetting", options.resetting);
    loadSearchParams(cfg, "HypothesisSearch", options.search);
    loadChallengerParams(cfg, "Challenger", options.challenger);
    options.lidar.loadFromConfig(cfg, "LidarModel");
}

}  // namespace simp::localization
