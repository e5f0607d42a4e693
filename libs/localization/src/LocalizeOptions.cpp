#include <simp/localization/LocalizeOptions.h>
#include <simp/localization/Localizer.h>
#include <simp/model/LocalizationMethods.h>

namespace simp::localization {
namespace {

constexpr const char* kExperiment = "LocalizationExperiment";
constexpr const char* kMotion = "MotionModel";

using io::ValueRange;

}  // namespace

const io::OptionTable<ExperimentOptions>& ExperimentOptions::table() {
    using O = ExperimentOptions;
    static const io::OptionTable<O> t = [] {
        std::vector<std::string> models{""};  // "": the [MetricMap] object map's own
        const auto& methods = model::localizationMethodNames();
        models.insert(models.end(), methods.begin(), methods.end());
        return io::OptionTable<O>(kExperiment)
            .integer("particles_count", &O::particles_count, ValueRange::atLeast(1), "initial particles (the paper: 5000)")
            .integer("seed", &O::seed, ValueRange::between(0, 4294967295.0), "random seed (mrpt::random::getRandomGenerator())")
            .choice("sensor_model", &O::sensor_model, models, "overrides the map's `sensor_model`; empty = the map's (`lidar`, `simp+lidar`: doc/lidar.md)")
            .number("free_cells_threshold", &O::free_cells_threshold, "", ValueRange::aboveUpTo(0, 1),
                    "free cell: p_free >= this (camera::floorplan::kParticleMinFree)")
            .flag("prune_outside_free_space", [](auto& o) -> auto& { return o.filter.prune_outside_free_space; }, "redraw particles moved off the free space")
            .number("update_min_d_xy", &O::update_min_d_xy, "m", ValueRange::nonNegative(), "motion that triggers an update (the paper's d_xy; 0 = every frame)")
            .number("update_min_d_phi", &O::update_min_d_phi, "rad", ValueRange::nonNegative(), "rotation that triggers an update (the paper's d_theta; 0 = every frame)")
            .flag("keep_skipped_detections", &O::keep_skipped_detections, "use the detections of the skipped frames at the next update")
            .flag("prune_keeps_weight", [](auto& o) -> auto& { return o.filter.prune_keeps_weight; }, "false: a pruned particle gets the smallest weight MRPT keeps (max log-weight - `max_loglikelihood_dyn_range`); "
                  "true: it keeps its weight (authors' code, simp-paper.ini)")
            .flag("resample_resets_weights", [](auto& o) -> auto& { return o.filter.resample_resets_weights; },
                  "true: equal weights after resampling (SIR); false: the copies keep their weights, as MRPT 2.5's "
                  "performResampling leaves them (simp-paper.ini)")
            .flag("singw_per_frame", [](auto& o) -> auto& { return o.filter.singw_per_frame; }, "Eq. singw per camera frame (time stamp), multiplied over the frames of an update; false = one geometric mean over the update")
            .number("recovery_alpha_slow", [](auto& o) -> auto& { return o.filter.recovery_alpha_slow; }, "", ValueRange::fraction(), "augmented-MCL long-term rate (0 = no recovery)")
            .number("recovery_alpha_fast", [](auto& o) -> auto& { return o.filter.recovery_alpha_fast; }, "", ValueRange::fraction(), "augmented-MCL short-term rate, > `recovery_alpha_slow` when not 0")
            .choice("estimate_mode", &O::estimate_mode,
                    std::vector<std::pair<std::string, EstimateMode>>{{"cluster", EstimateMode::Cluster}, {"mean", EstimateMode::Mean}},
                    "`estimate.tum`: mean of the highest-weight cluster, or of all particles")
            .number("cluster_radius_m", &O::cluster_radius_m, "m", ValueRange::positive(), "cluster: particles within this distance of the peak")
            .number("cluster_max_dphi", &O::cluster_max_dphi, "rad", ValueRange::positive(), "cluster: and within this heading difference")
            .number("cluster_cell_m", &O::cluster_cell_m, "m", ValueRange::positive(), "cluster: xy bin size used to find the peak")
            .integer("cluster_phi_bins", &O::cluster_phi_bins, ValueRange::between(1, 360), "cluster: heading bins used to find the peak")
            .integer("tracking_min_particles", &O::tracking_min_particles, ValueRange::between(0, 1e7),
                     "while localized, KLD-bounded count between this and `particles_count`; 0 = fixed count (simp-paper.ini)")
            .number("min_spread_xy_m", &O::min_spread_xy_m, "m", ValueRange::between(0, 5),
                    "floor on the reported cluster's per-axis position std: a tighter set is widened (0 = off, simp-paper.ini)")
            .number("min_spread_phi_rad", &O::min_spread_phi_rad, "rad", ValueRange::between(0, M_PI),
                    "floor on the reported cluster's heading std (0 = off)")
            .number("lost_detection_power", &O::lost_detection_power, "", ValueRange::fraction(),
                    "while lost, the filter's own set weighs the detections with this exponent (the challenger's fully); 1 = as always")
            .choice("report_from", &O::report_from,
                    std::vector<std::pair<std::string, ReportFrom>>{{"localized", ReportFrom::Localized}, {"start", ReportFrom::Start}},
                    "first line of `estimate.tum`: first step in state localized, or first frame")
            .flag("write_particles", &O::write_particles, "write `final_particles.txt`")
            .flag("write_png", &O::write_png, "write `trajectory.png`")
            .rule("recovery_alpha_slow", [](const O& o) { return o.filter.recovery_alpha_fast == 0.0 || o.filter.recovery_alpha_slow < o.filter.recovery_alpha_fast; },
                  "be smaller than recovery_alpha_fast (when that is > 0)");
    }();
    return t;
}

void ExperimentOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void ExperimentOptions::dumpToTextStream(std::ostream& out) const { table().dump(*this, out); }

const io::OptionTable<MotionModelOptions>& MotionModelOptions::table() {
    using M = mrpt::obs::CActionRobotMovement2D;
    // The fields are MRPT's TMotionModelOptions; the .ini keys are its field names.
    static const io::OptionTable<MotionModelOptions> t =
        io::OptionTable<MotionModelOptions>(kMotion)
            .choice("modelSelection", [](auto& o) -> auto& { return o.mrpt_options.modelSelection; },
                    std::vector<std::pair<std::string, M::TDrawSampleMotionModel>>{{"gaussian", M::mmGaussian}, {"thrun", M::mmThrun}},
                    "MRPT's odometry noise model")
            .number("a1", [](auto& o) -> auto& { return o.mrpt_options.gaussianModel.a1; }, "m/m", ValueRange::nonNegative(), "gaussian: translation std per metre")
            .number("a2", [](auto& o) -> auto& { return o.mrpt_options.gaussianModel.a2; }, "m/rad", ValueRange::nonNegative(), "gaussian: translation std per radian")
            .number("a3", [](auto& o) -> auto& { return o.mrpt_options.gaussianModel.a3; }, "rad/m", ValueRange::nonNegative(), "gaussian: rotation std per metre")
            .number("a4", [](auto& o) -> auto& { return o.mrpt_options.gaussianModel.a4; }, "rad/rad", ValueRange::nonNegative(), "gaussian: rotation std per radian")
            .number("minStdXY", [](auto& o) -> auto& { return o.mrpt_options.gaussianModel.minStdXY; }, "m", ValueRange::nonNegative(), "gaussian: least translation std")
            .number("minStdPHI", [](auto& o) -> auto& { return o.mrpt_options.gaussianModel.minStdPHI; }, "rad", ValueRange::nonNegative(), "gaussian: least rotation std")
            .integer("nParticlesCount", [](auto& o) -> auto& { return o.mrpt_options.thrunModel.nParticlesCount; }, ValueRange::atLeast(1), "thrun: samples")
            .number("alfa1_rot_rot", [](auto& o) -> auto& { return o.mrpt_options.thrunModel.alfa1_rot_rot; }, "", ValueRange::nonNegative(), "thrun")
            .number("alfa2_rot_trans", [](auto& o) -> auto& { return o.mrpt_options.thrunModel.alfa2_rot_trans; }, "", ValueRange::nonNegative(), "thrun")
            .number("alfa3_trans_trans", [](auto& o) -> auto& { return o.mrpt_options.thrunModel.alfa3_trans_trans; }, "", ValueRange::nonNegative(), "thrun")
            .number("alfa4_trans_rot", [](auto& o) -> auto& { return o.mrpt_options.thrunModel.alfa4_trans_rot; }, "", ValueRange::nonNegative(), "thrun")
            .number("additional_std_XY", [](auto& o) -> auto& { return o.mrpt_options.thrunModel.additional_std_XY; }, "m", ValueRange::nonNegative(), "thrun")
            .number("additional_std_phi", [](auto& o) -> auto& { return o.mrpt_options.thrunModel.additional_std_phi; }, "rad", ValueRange::nonNegative(), "thrun");
    return t;
}

void MotionModelOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& s) { table().load(cfg, s, *this); }
void MotionModelOptions::dumpToTextStream(std::ostream& out) const { table().dump(*this, out); }

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
    options.heading.loadFromConfig(cfg, "ManhattanHeading");
}

}  // namespace simp::localization
