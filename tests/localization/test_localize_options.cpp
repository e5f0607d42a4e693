/// The project's .ini keys: defaults, validation, the paper's motion model.

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <simp/io/StrictIni.h>
#include <simp/localization/Localizer.h>

using namespace simp::localization;

TEST(LocalizeOptions, DefaultsAreThePapers) {
    const ExperimentOptions e;
    EXPECT_EQ(e.particles_count, 5000u);
    EXPECT_DOUBLE_EQ(e.update_min_d_xy, 0.10);
    EXPECT_DOUBLE_EQ(e.update_min_d_phi, 0.03);
    EXPECT_TRUE(e.filter.singw_per_frame);
    EXPECT_FALSE(e.filter.prune_keeps_weight);  // simp.ini's (the paper's true is in simp-paper.ini)
    EXPECT_DOUBLE_EQ(e.filter.recovery_alpha_fast, 0.0);  // recovery is not the paper's: off
    const auto m = MotionModelOptions::paperDefaults();
    EXPECT_EQ(m.modelSelection, mrpt::obs::CActionRobotMovement2D::mmGaussian);
    EXPECT_DOUBLE_EQ(m.gaussianModel.a1, 0.15);
    EXPECT_DOUBLE_EQ(m.gaussianModel.a4, 0.15);
}

TEST(LocalizeOptions, MotionModelGivesTheNoiseOfTheIncrement) {
    // sigma = minStd + 0.15 * |motion|: a 1 m straight move has sigma_x = 0.01 + 0.15 m.
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(mrpt::poses::CPose2D(1, 0, 0), MotionModelOptions::paperDefaults());
    mrpt::math::CMatrixDouble33 cov;
    mrpt::poses::CPose2D mean;
    mv.poseChange->getCovarianceAndMean(cov, mean);
    EXPECT_NEAR(std::sqrt(cov(0, 0)), 0.16, 1e-9);
    EXPECT_NEAR(std::sqrt(cov(2, 2)), 0.01, 1e-9);
    // A pure 1 rad turn: sigma_phi = 0.01 + 0.15 rad.
    mv.computeFromOdometry(mrpt::poses::CPose2D(0, 0, 1), MotionModelOptions::paperDefaults());
    mv.poseChange->getCovarianceAndMean(cov, mean);
    EXPECT_NEAR(std::sqrt(cov(2, 2)), 0.16, 1e-9);
}

TEST(LocalizeOptions, LoadsEveryKey) {
    const simp::io::StrictIni cfg(
        "[LocalizationExperiment]\nparticles_count=123\nseed=9\nsensor_model=d\nfree_cells_threshold=0.6\n"
        "prune_outside_free_space=false\nupdate_min_d_xy=0.2\nupdate_min_d_phi=0.1\nestimate_mode=mean\n"
        "prune_keeps_weight=false\nsingw_per_frame=false\nrecovery_alpha_slow=0.001\nrecovery_alpha_fast=0.1\n"
        "min_spread_xy_m=0.12\nmin_spread_phi_rad=0.06\n"
        "[MotionModel]\nmodelSelection=thrun\nalfa1_rot_rot=0.2\na1=0.3\n",
        "x.ini");
    LocalizerOptions all;
    loadLocalizerOptions(cfg, all);
    cfg.checkUnknown();
    ExperimentOptions e;
    e.loadFromConfigFile(cfg, "LocalizationExperiment");
    EXPECT_EQ(e.particles_count, 123u);
    EXPECT_EQ(e.seed, 9u);
    EXPECT_EQ(e.sensor_model, "d");
    EXPECT_DOUBLE_EQ(e.free_cells_threshold, 0.6);
    EXPECT_FALSE(e.filter.prune_outside_free_space);
    EXPECT_DOUBLE_EQ(e.update_min_d_xy, 0.2);
    EXPECT_EQ(e.estimate_mode, EstimateMode::Mean);
    EXPECT_FALSE(e.filter.singw_per_frame);
    EXPECT_FALSE(e.filter.prune_keeps_weight);
    EXPECT_DOUBLE_EQ(e.filter.recovery_alpha_slow, 0.001);
    EXPECT_DOUBLE_EQ(e.filter.recovery_alpha_fast, 0.1);
    EXPECT_DOUBLE_EQ(e.min_spread_xy_m, 0.12);
    EXPECT_DOUBLE_EQ(e.min_spread_phi_rad, 0.06);
    MotionModelOptions m;
    m.loadFromConfigFile(cfg, "MotionModel");
    EXPECT_EQ(m.mrpt_options.modelSelection, mrpt::obs::CActionRobotMovement2D::mmThrun);
    EXPECT_FLOAT_EQ(m.mrpt_options.thrunModel.alfa1_rot_rot, 0.2f);
    EXPECT_DOUBLE_EQ(m.mrpt_options.gaussianModel.a1, 0.3);
}

TEST(LocalizeOptions, RejectsUnknownKeysAndBadValuesByName) {
    auto message = [](const std::string& ini) {
        try {
            const simp::io::StrictIni cfg(ini, "my.ini");
            LocalizerOptions all;
            loadLocalizerOptions(cfg, all);
            cfg.checkUnknown();
        } catch (const std::exception& ex) {
            return std::string(ex.what());
        }
        return std::string();
    };
    std::string m = message("[LocalizationExperiment]\nparticle=5\n");
    EXPECT_NE(m.find("my.ini"), std::string::npos);
    EXPECT_NE(m.find("'particle'"), std::string::npos);
    // MRPT's [PF_options] has required keys: a section with all of them plus a misspelt one.
    const std::string pf = "[PF_options]\nPF_algorithm=pfStandardProposal\nresamplingMethod=prSystematic\n"
                           "adaptiveSampleSize=false\nBETA=0.5\nsampleSize=1\npowFactor=1\n"
                           "max_loglikelihood_dyn_range=15\npfAuxFilterOptimal_MaximumSearchSamples=100\n";
    EXPECT_NE(message(pf + "BETTA=0.5\n").find("my.ini: [PF_options] unknown key 'BETTA'"), std::string::npos)
        << message(pf + "BETTA=0.5\n");
    EXPECT_NE(message("[PF_options]\nBETA=0.5\n").find("Value for 'adaptiveSampleSize' not found"), std::string::npos);
    EXPECT_NE(message("[KLD_options]\nKLD_size=1\n").find("KLD_size"), std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nparticles_count=-3\n").find("particles_count"), std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nparticles_count=12.5\n").find("particles_count"), std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nseed=abc\n").find("seed"), std::string::npos);
    // lidar and simp+lidar are sensor models since issue #17 (doc/lidar.md); a misspelt one is not
    EXPECT_NE(message("[LocalizationExperiment]\nsensor_model=laser\n").find("laser"), std::string::npos);
    EXPECT_EQ(message("[LocalizationExperiment]\nsensor_model=simp+lidar\n"), "");
    EXPECT_NE(message("[LocalizationExperiment]\nestimate_mode=median\n").find("estimate_mode"), std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nupdate_min_d_xy=nan\n").find("update_min_d_xy"), std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nprune_outside_free_space=maybe\n").find("prune"), std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nrecovery_alpha_slow=0.2\nrecovery_alpha_fast=0.1\n").find("recovery_alpha_slow"),
              std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nrecovery_alpha_fast=1.5\n").find("recovery_alpha"), std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nsingw_per_frame=sometimes\n").find("singw_per_frame"), std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nmin_spread_xy_m=-0.1\n").find("min_spread_xy_m"), std::string::npos);
    EXPECT_NE(message("[LocalizationExperiment]\nmin_spread_phi_rad=4\n").find("min_spread_phi_rad"), std::string::npos);
    EXPECT_NE(message("[MotionModel]\nmodelSelection=magic\n").find("modelSelection"), std::string::npos);
    EXPECT_EQ(message("[LocalizationExperiment]\nparticles_count=10\n"), "");
    // MRPT's own option structs are checked too: a value MRPT's atoi would read as 0.
    m = message("[KLD_options]\nKLD_maxSampleSize=abc\n");
    EXPECT_NE(m.find("my.ini: [KLD_options] KLD_maxSampleSize"), std::string::npos) << m;
    const std::string bad_beta = message(std::string(pf).replace(pf.find("BETA=0.5"), 8, "BETA=0.5x"));
    EXPECT_NE(bad_beta.find("BETA"), std::string::npos) << bad_beta;
    EXPECT_NE(message("[Localization]\nparticles_count=10\n").find("unknown section [Localization]"), std::string::npos);
    EXPECT_NE(message("particles_count=10\n").find("outside any [section]"), std::string::npos);
    EXPECT_NE(message("garbage\n").find("neither [section] nor key = value"), std::string::npos);
}
