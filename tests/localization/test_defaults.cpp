/// simp-localize without --config runs exactly as with config_ini/simp.ini: the compiled-in defaults
/// equal the shipped .ini field by field, and a run on the simulator's built-in office (which has
/// classes without a noise model, e.g. door) gives the same numbers either way. Turning on KLD alone
/// works (the loader picks the resampling MRPT needs).

#include "TestUtil.h"

#include <gtest/gtest.h>
#include <mrpt/io/vector_loadsave.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/SimApp.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace simp::localization;

namespace {

const std::string kSimpIni = std::string(SIMP_SOURCE_DIR) + "/config_ini/simp.ini";

/// initialize() with `config` ("" = no --config): the options and the .ini content, nothing run.
void initializeWith(LocalizeApp& app, const std::string& config) {
    std::vector<std::string> args{"simp-localize", "--world", "w", "--rawlog", "q.rawlog", "--out", "o", "--quiet"};
    if (!config.empty()) args.insert(args.end(), {"--config", config});
    app.initialize(args);
}

// One EXPECT per field, naming it: a key added to simp.ini or a default changed alone shows here.
#define SIMP_EXPECT_SAME(field) EXPECT_EQ(a.field, b.field) << #field

void expectSame(const ExperimentOptions& a, const ExperimentOptions& b) {
    SIMP_EXPECT_SAME(particles_count);
    SIMP_EXPECT_SAME(seed);
    SIMP_EXPECT_SAME(sensor_model);
    SIMP_EXPECT_SAME(free_cells_threshold);
    SIMP_EXPECT_SAME(filter.prune_outside_free_space);
    SIMP_EXPECT_SAME(update_min_d_xy);
    SIMP_EXPECT_SAME(update_min_d_phi);
    SIMP_EXPECT_SAME(keep_skipped_detections);
    SIMP_EXPECT_SAME(filter.prune_keeps_weight);
    SIMP_EXPECT_SAME(filter.singw_per_frame);
    SIMP_EXPECT_SAME(filter.recovery_alpha_slow);
    SIMP_EXPECT_SAME(filter.recovery_alpha_fast);
    SIMP_EXPECT_SAME(estimate_mode);
    SIMP_EXPECT_SAME(cluster_radius_m);
    SIMP_EXPECT_SAME(cluster_max_dphi);
    SIMP_EXPECT_SAME(cluster_cell_m);
    SIMP_EXPECT_SAME(cluster_phi_bins);
    SIMP_EXPECT_SAME(tracking_min_particles);
    SIMP_EXPECT_SAME(min_spread_xy_m);
    SIMP_EXPECT_SAME(min_spread_phi_rad);
    SIMP_EXPECT_SAME(report_from);
    SIMP_EXPECT_SAME(write_particles);
    SIMP_EXPECT_SAME(write_png);
}

void expectSame(const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions& a,
                const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions& b) {
    SIMP_EXPECT_SAME(modelSelection);
    SIMP_EXPECT_SAME(gaussianModel.a1);
    SIMP_EXPECT_SAME(gaussianModel.a2);
    SIMP_EXPECT_SAME(gaussianModel.a3);
    SIMP_EXPECT_SAME(gaussianModel.a4);
    SIMP_EXPECT_SAME(gaussianModel.minStdXY);
    SIMP_EXPECT_SAME(gaussianModel.minStdPHI);
    SIMP_EXPECT_SAME(thrunModel.nParticlesCount);
    SIMP_EXPECT_SAME(thrunModel.alfa1_rot_rot);
    SIMP_EXPECT_SAME(thrunModel.alfa2_rot_trans);
    SIMP_EXPECT_SAME(thrunModel.alfa3_trans_trans);
    SIMP_EXPECT_SAME(thrunModel.alfa4_trans_rot);
    SIMP_EXPECT_SAME(thrunModel.additional_std_XY);
    SIMP_EXPECT_SAME(thrunModel.additional_std_phi);
}

void expectSame(const mrpt::bayes::CParticleFilter::TParticleFilterOptions& a,
                const mrpt::bayes::CParticleFilter::TParticleFilterOptions& b) {
    SIMP_EXPECT_SAME(PF_algorithm);
    SIMP_EXPECT_SAME(resamplingMethod);
    SIMP_EXPECT_SAME(adaptiveSampleSize);
    SIMP_EXPECT_SAME(BETA);
    SIMP_EXPECT_SAME(sampleSize);
    SIMP_EXPECT_SAME(powFactor);
    SIMP_EXPECT_SAME(max_loglikelihood_dyn_range);
    SIMP_EXPECT_SAME(pfAuxFilterOptimal_MaximumSearchSamples);
    SIMP_EXPECT_SAME(pfAuxFilterStandard_FirstStageWeightsMonteCarlo);
    SIMP_EXPECT_SAME(pfAuxFilterOptimal_MLE);
}

void expectSame(const mrpt::slam::TKLDParams& a, const mrpt::slam::TKLDParams& b) {
    SIMP_EXPECT_SAME(KLD_binSize_XY);
    SIMP_EXPECT_SAME(KLD_binSize_PHI);
    SIMP_EXPECT_SAME(KLD_delta);
    SIMP_EXPECT_SAME(KLD_epsilon);
    SIMP_EXPECT_SAME(KLD_minSampleSize);
    SIMP_EXPECT_SAME(KLD_maxSampleSize);
    SIMP_EXPECT_SAME(KLD_minSamplesPerBin);
}

void expectSame(const StateParams& a, const StateParams& b) {
    SIMP_EXPECT_SAME(fit_window);
    SIMP_EXPECT_SAME(fit_max_age_s);
    SIMP_EXPECT_SAME(fit_min_detections);
    SIMP_EXPECT_SAME(explained_ratio);
    SIMP_EXPECT_SAME(localized_min_fit);
    SIMP_EXPECT_SAME(localized_min_weight);
    SIMP_EXPECT_SAME(localized_max_std_m);
    SIMP_EXPECT_SAME(localized_min_updates);
    SIMP_EXPECT_SAME(lost_window);
    SIMP_EXPECT_SAME(lost_max_fit);
    SIMP_EXPECT_SAME(lost_tolerance_m);
    SIMP_EXPECT_SAME(lost_tolerance_rad);
    SIMP_EXPECT_SAME(lost_min_weight);
    SIMP_EXPECT_SAME(rival_margin);
    SIMP_EXPECT_SAME(rival_lost_margin);
}

void expectSame(const HypothesisSearchParams& a, const HypothesisSearchParams& b) {
    SIMP_EXPECT_SAME(enabled);
    SIMP_EXPECT_SAME(min_window_detections);
    SIMP_EXPECT_SAME(max_candidates);
    SIMP_EXPECT_SAME(pair_candidates);
    SIMP_EXPECT_SAME(pairs.min_separation_m);
    SIMP_EXPECT_SAME(pairs.tolerance_m);
    SIMP_EXPECT_SAME(pairs.merge_radius_m);
    SIMP_EXPECT_SAME(refine_top);
    SIMP_EXPECT_SAME(refine_step_m);
    SIMP_EXPECT_SAME(refine_step_rad);
    SIMP_EXPECT_SAME(distinct_distance_m);
    SIMP_EXPECT_SAME(distinct_heading_rad);
    SIMP_EXPECT_SAME(max_hypotheses);
    SIMP_EXPECT_SAME(while_global);
    SIMP_EXPECT_SAME(while_localized);
    SIMP_EXPECT_SAME(check_period_s);
}

void expectSame(const ChallengerParams& a, const ChallengerParams& b) {
    SIMP_EXPECT_SAME(enabled);
    SIMP_EXPECT_SAME(win_margin);
    SIMP_EXPECT_SAME(agree_distance_m);
    SIMP_EXPECT_SAME(reset_fraction);
    SIMP_EXPECT_SAME(reset_by_fit);
    SIMP_EXPECT_SAME(hypothesis_search);
    SIMP_EXPECT_SAME(particles);
    SIMP_EXPECT_SAME(window);
    SIMP_EXPECT_SAME(window_max_age_s);
    SIMP_EXPECT_SAME(replace_max_fit);
}

void expectSame(const SensorResettingParams& a, const SensorResettingParams& b) {
    SIMP_EXPECT_SAME(global_fraction);
    SIMP_EXPECT_SAME(lost_fraction);
    SIMP_EXPECT_SAME(localized_fraction);
    SIMP_EXPECT_SAME(local_fraction);
    SIMP_EXPECT_SAME(local_position_std_m);
    SIMP_EXPECT_SAME(local_heading_std_rad);
    SIMP_EXPECT_SAME(uniform_share);
    SIMP_EXPECT_SAME(sampler.position_std_m);
    SIMP_EXPECT_SAME(sampler.heading_std_rad);
    SIMP_EXPECT_SAME(sampler.square_ratio);
}

void expectSame(const LidarModelOptions& a, const LidarModelOptions& b) {
    SIMP_EXPECT_SAME(weight);
    SIMP_EXPECT_SAME(decimation);
    SIMP_EXPECT_SAME(sigma_m);
    SIMP_EXPECT_SAME(z_hit);
    SIMP_EXPECT_SAME(z_random);
    SIMP_EXPECT_SAME(max_range_m);
    SIMP_EXPECT_SAME(max_corr_distance_m);
    SIMP_EXPECT_SAME(min_range_m);
    SIMP_EXPECT_SAME(beam_skip_distance_m);
    SIMP_EXPECT_SAME(beam_skip_threshold);
    SIMP_EXPECT_SAME(beam_skip_max_fraction);
    SIMP_EXPECT_SAME(map_objects);
}

void expectSame(const ManhattanHeadingOptions& a, const ManhattanHeadingOptions& b) {
    SIMP_EXPECT_SAME(weight);
    SIMP_EXPECT_SAME(yaw_sigma_rad);
    SIMP_EXPECT_SAME(aligned_tolerance_rad);
    SIMP_EXPECT_SAME(min_aligned_fraction);
    SIMP_EXPECT_SAME(outlier_fraction);
}

void expectSame(const DetectionNoveltyParams& a, const DetectionNoveltyParams& b) {
    SIMP_EXPECT_SAME(decorrelation_distance_m);
    SIMP_EXPECT_SAME(min_weight);
    SIMP_EXPECT_SAME(view_change_weight);
    SIMP_EXPECT_SAME(track_radius_m);
    SIMP_EXPECT_SAME(track_timeout_s);
    SIMP_EXPECT_SAME(unmapped_min_detections);
    SIMP_EXPECT_SAME(unmapped_min_span_s);
    SIMP_EXPECT_SAME(unmapped_max_explained);
    SIMP_EXPECT_SAME(unmapped_min_fit);
    SIMP_EXPECT_SAME(unmapped_while_lost);
    SIMP_EXPECT_SAME(unmapped_tolerance_m);
    SIMP_EXPECT_SAME(unmapped_tolerance_rad);
}

void expectSame(const simp::maps::CObjectMap::TLikelihoodOptions& a,
                const simp::maps::CObjectMap::TLikelihoodOptions& b) {
    SIMP_EXPECT_SAME(sensor_model);
    EXPECT_TRUE(a.modelParams() == b.modelParams()) << "eta, m_p, skip_classes_without_noise, edt_*, noise range, centre noise";
    SIMP_EXPECT_SAME(skip_classes_without_noise);
    SIMP_EXPECT_SAME(unmodelled_noise_std_m);
    SIMP_EXPECT_SAME(noise_reference_range_m);
    SIMP_EXPECT_SAME(yaw_sigma_rad);
    SIMP_EXPECT_SAME(mp_centre_noise_floor);
    SIMP_EXPECT_SAME(default_confidence_threshold);
    for (const auto& name : simp::obs::defaultClassNames()) EXPECT_EQ(a.thresholdOf(name), b.thresholdOf(name)) << name;
}
#undef SIMP_EXPECT_SAME

/// The built-in office world and a 20 s sequence, made once per test process with simp-sim's app,
/// in a folder of the running test's own (CTest runs the tests of this file in parallel processes).
struct OfficeRun {
    std::string world, rawlog;
};
const OfficeRun& builtinOffice() {
    static const OfficeRun run = [] {
        const fs::path dir = fs::path(SIMP_TEST_OUTPUT_DIR) / "localization" /
                             (std::string("defaults_office_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        std::ostringstream out;
        for (const std::vector<std::string>& args :
             {std::vector<std::string>{"world", "--builtin", "office", "--seed", "5", "--out", (dir / "w").string()},
              std::vector<std::string>{"sequence", "--world", (dir / "w").string(), "--seed", "6", "--out",
                                       (dir / "q").string(), "--duration", "20"}}) {
            simp::sim::SimApp sim;
            if (sim.initialize(args, out)) sim.run(out);
        }
        return OfficeRun{(dir / "w").string(), (dir / "q" / "sequence.rawlog").string()};
    }();
    return run;
}

std::vector<std::string> officeArgs(const std::string& out) {
    const auto& o = builtinOffice();
    return {"--world", o.world, "--rawlog", o.rawlog, "--out", out, "--particles", "1500", "--seed", "2"};
}

}  // namespace

TEST(LocalizeDefaults, CompiledInDefaultsEqualSimpIniFieldByField) {
    LocalizeApp a, b;
    initializeWith(a, "");
    initializeWith(b, kSimpIni);
    expectSame(a.options.experiment, b.options.experiment);
    expectSame(a.options.motion.mrpt_options, b.options.motion.mrpt_options);
    expectSame(a.options.pf, b.options.pf);
    expectSame(a.options.kld, b.options.kld);
    expectSame(a.options.state, b.options.state);
    expectSame(a.options.novelty, b.options.novelty);
    expectSame(a.options.resetting, b.options.resetting);
    expectSame(a.options.search, b.options.search);
    expectSame(a.options.challenger, b.options.challenger);
    expectSame(a.options.lidar, b.options.lidar);
    expectSame(a.options.heading, b.options.heading);
    expectSame(makeObjectMap(*a.params, "")->likelihoodOptions, makeObjectMap(*b.params, kSimpIni)->likelihoodOptions);
    EXPECT_TRUE(a.config_notes.empty());
    EXPECT_TRUE(b.config_notes.empty());
}

TEST(LocalizeDefaults, WithoutConfigTheBuiltInOfficeLocalizesAsWithSimpIni) {
    // The office has doors and chairs, classes without a noise model: the defaults must score them
    // as simp.ini does (unmodelled_noise_std_m).
    LocalizeApp plain, with_ini;
    test::runApp(plain, officeArgs(test::freshOutputDir("defaults_plain")));
    auto args = officeArgs(test::freshOutputDir("defaults_ini"));
    args.insert(args.end(), {"--config", kSimpIni});
    test::runApp(with_ini, args);
    EXPECT_EQ(plain.sensor_model_used, "simp");
    ASSERT_GT(plain.steps.size(), 100u);  // 20 s of 10 Hz odometry
    ASSERT_EQ(plain.steps.size(), with_ini.steps.size());
    for (std::size_t i = 0; i < plain.steps.size(); ++i) {
        const auto& p = plain.steps[i];
        const auto& q = with_ini.steps[i];
        ASSERT_EQ(p.estimate.x, q.estimate.x) << "step " << i;
        ASSERT_EQ(p.estimate.y, q.estimate.y) << "step " << i;
        ASSERT_EQ(p.estimate.phi, q.estimate.phi) << "step " << i;
        ASSERT_EQ(p.state, q.state) << "step " << i;
    }
    EXPECT_EQ(plain.final_particles.size(), with_ini.final_particles.size());
}

TEST(LocalizeDefaults, KldOnAloneSetsMultinomialResamplingAndSaysSo) {
    // simp.ini with adaptiveSampleSize = true and nothing else changed (it keeps prSystematic).
    std::string text = mrpt::io::file_get_contents(kSimpIni);
    text = std::regex_replace(text, std::regex("adaptiveSampleSize = false"), "adaptiveSampleSize = true");
    ASSERT_NE(text.find("adaptiveSampleSize = true"), std::string::npos);
    const std::string out = test::freshOutputDir("defaults_kld");
    fs::create_directories(out);
    const std::string ini = out + "/kld.ini";
    std::ofstream(ini) << text;

    LocalizeApp app;
    std::ostringstream log;
    app.log = &log;
    auto args = officeArgs(out);
    args.insert(args.end(), {"--config", ini});
    test::runApp(app, args);
    EXPECT_EQ(app.options.pf.resamplingMethod, mrpt::bayes::CParticleFilter::prMultinomial);
    ASSERT_EQ(app.config_notes.size(), 1u);
    EXPECT_NE(log.str().find("resamplingMethod set to prMultinomial"), std::string::npos) << log.str();
    // KLD sampling sized the set within [KLD_minSampleSize, KLD_maxSampleSize] = [1000, 20000].
    EXPECT_GE(app.final_particles.size(), 1000u);
    EXPECT_LE(app.final_particles.size(), 20000u);
    EXPECT_GT(app.steps.size(), 100u);
}
