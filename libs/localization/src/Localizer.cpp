#include <simp/localization/Localizer.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace simp::localization {
namespace {

/// The action of one filter step: the odometry increment with the [MotionModel] noise.
mrpt::obs::CActionCollection makeAction(const mrpt::poses::CPose2D& increment, const MotionModelOptions& motion) {
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(increment, motion.mrpt_options);
    mrpt::obs::CActionCollection acts;
    acts.insert(mv);
    return acts;
}

HypothesisSearchParams alwaysEnabled(HypothesisSearchParams p) {
    p.enabled = true;
    return p;
}

/// `count` poses about `targets` in equal shares (position_std_m, heading_std_rad of the sampler),
/// those in the free space.
std::vector<mrpt::math::TPose2D> drawAbout(const std::vector<Hypothesis>& targets, std::size_t count,
                                           const DetectionPoseSamplerParams& sp, const FreeSpace& free) {
    auto& rng = mrpt::random::getRandomGenerator();
    std::vector<mrpt::math::TPose2D> poses;
    for (std::size_t j = 0; j < count; ++j) {
        const auto& h = targets[j % targets.size()].pose;
        const mrpt::math::TPose2D p(h.x + rng.drawGaussian1D(0.0, sp.position_std_m),
                                    h.y + rng.drawGaussian1D(0.0, sp.position_std_m),
                                    mrpt::math::wrapToPi(h.phi + rng.drawGaussian1D(0.0, sp.heading_std_rad)));
        if (free.isFree(p.x, p.y)) poses.push_back(p);
    }
    return poses;
}

/// [State] with the challenger's window ([Challenger] window, window_max_age_s).
StateParams challengerWindow(const LocalizerOptions& options) {
    StateParams p = options.state;
    p.fit_window = options.challenger.window;
    p.fit_max_age_s = options.challenger.window_max_age_s;
    return p;
}

}  // namespace

mrpt::bayes::CParticleFilter::TParticleFilterOptions LocalizerOptions::defaultPfOptions() {
    mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
    o.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
    o.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
    o.adaptiveSampleSize = false;
    o.BETA = 0.5;
    o.sampleSize = 1;
    return o;
}

mrpt::slam::TKLDParams LocalizerOptions::defaultKldParams() {
    mrpt::slam::TKLDParams k;
    k.KLD_binSize_XY = 0.20;                  // m
    k.KLD_binSize_PHI = mrpt::DEG2RAD(5.0);   // rad (the .ini gives degrees)
    k.KLD_delta = 0.01;
    k.KLD_epsilon = 0.02;
    k.KLD_minSampleSize = 1000;
    k.KLD_maxSampleSize = 20000;
    k.KLD_minSamplesPerBin = 0;
    return k;
}

Localizer::Localizer(std::shared_ptr<const maps::CObjectMap> map, const mrpt::maps::COccupancyGridMap2D& floorplan,
                     const LocalizerOptions& options)
    : m_map(std::move(map)),
      m_floorplan(floorplan),
      m_opts(options),
      m_free(std::make_shared<FreeSpace>(floorplan, options.experiment.free_cells_threshold)),
      m_mcl(makeFilter()),
      m_novelty(options.novelty),
      m_sampler(*m_map, *m_free, options.resetting.sampler),
      m_search(*m_map, m_sampler, options.search),
      m_challenger_search(*m_map, m_sampler, alwaysEnabled(options.search)),
      m_fit(options.state),
      m_since_lost(challengerWindow(options)),
      m_monitor(options.state),
      m_scans_since_lost(options.challenger.scan_window),
      m_views_since_lost(options.challenger.views, floorplan) {
    m_pf.m_options = m_opts.pf;
    if (m_opts.heading.weight > 0.0) {
        m_heading.emplace(*m_map, m_opts.heading);
        if (!m_heading->active()) m_heading.reset();  // no dominant axes in this map
    }
}

std::unique_ptr<ObjectMcl> Localizer::makeFilter() const {
    const auto& e = m_opts.experiment;
    auto mcl = std::make_unique<ObjectMcl>(m_map);
    mcl->options.KLD_params = m_opts.kld;
    mcl->params = e.filter;
    mcl->setFreeSpace(m_free);
    return mcl;
}

void Localizer::resetUniform(ObjectMcl& mcl, std::size_t n) const {
    auto grid = m_floorplan;  // MRPT's reset takes a non-const map
    mcl.resetUniformFreeSpace(&grid, m_opts.experiment.free_cells_threshold, static_cast<int>(n));
}

ParticleSummary Localizer::keepSpread(ObjectMcl& mcl, const ParticleSummary& summary) const {
    const auto& e = m_opts.experiment;
    const Eigen::Matrix3d& c = summary.cluster_cov;
    const double var_xy = 0.5 * (c(0, 0) + c(1, 1));  // per axis
    const double add_xy = e.min_spread_xy_m * e.min_spread_xy_m - var_xy;
    const double add_phi = e.min_spread_phi_rad * e.min_spread_phi_rad - c(2, 2);
    if (!(add_xy > 0) && !(add_phi > 0)) return summary;
    mcl.jitter(add_xy > 0 ? std::sqrt(add_xy) : 0.0, add_phi > 0 ? std::sqrt(add_phi) : 0.0);
    return summarizeParticles(mcl, e);
}

void Localizer::startGlobal() {
    resetUniform(*m_mcl, m_opts.experiment.particles_count);
    m_monitor.reset(LocalizationState::Global);
    m_summary.reset();
    m_challenger.reset();
    m_last_search_s = -std::numeric_limits<double>::infinity();
    m_first = true;
    m_entered_localized = false;
    m_local_target.reset();
}

void Localizer::startAt(const mrpt::math::TPose2D& pose, double sigma_xy_m, double sigma_phi_rad) {
    if (!m_free->isFree(pose.x, pose.y))
        throw std::invalid_argument("initial pose (" + std::to_string(pose.x) + ", " + std::to_string(pose.y) +
                                    ") is not in the floor plan's free space");
    if (!(sigma_xy_m >= 0 && sigma_phi_rad >= 0))
        throw std::invalid_argument("initial pose: sigma_xy and sigma_phi must be >= 0");
    m_mcl->resetAround(pose, sigma_xy_m, sigma_phi_rad, m_opts.experiment.particles_count);
    m_monitor.reset(LocalizationState::Localized);
    m_summary.reset();
    m_challenger.reset();
    m_last_search_s = -std::numeric_limits<double>::infinity();
    m_first = true;
    m_entered_localized = false;
    m_local_target.reset();
}

std::size_t Localizer::particleTarget(const ObjectMcl& mcl, LocalizationState state) const {
    const std::size_t full = m_opts.experiment.particles_count;
    if (m_opts.experiment.tracking_min_particles == 0) return mcl.size();
    if (state != LocalizationState::Localized) return full;
    auto kld = m_opts.kld;
    kld.KLD_minSampleSize = static_cast<unsigned>(std::min(m_opts.experiment.tracking_min_particles, full));
    kld.KLD_maxSampleSize = static_cast<unsigned>(full);
    return kldParticleCount(mcl, kld);
}

std::size_t Localizer::injectFromDetections(ObjectMcl& mcl, LocalizationState state,
                                            const std::vector<WeightedObservation>& observations) {
    const auto& r = m_opts.resetting;
    const bool challenger = &mcl != m_mcl.get();
    const double fraction = challenger ? m_opts.challenger.reset_fraction *
                                             (m_opts.challenger.reset_by_fit ? m_challenger->unexplained : 1.0)
                            : state == LocalizationState::Global   ? r.global_fraction
                            : state == LocalizationState::Lost     ? r.lost_fraction
                                                                   : r.localized_fraction;
    const auto count = static_cast<std::size_t>(std::lround(fraction * static_cast<double>(mcl.size())));
    if (count == 0) return 0;
    const auto n_uniform = static_cast<std::size_t>(std::lround(r.uniform_share * static_cast<double>(count)));
    auto& rng = mrpt::random::getRandomGenerator();
    std::vector<mrpt::math::TPose2D> poses;
    if (!m_hypotheses.empty() && !challenger) {
        // Around the places that explain the fit window best, in equal shares: the weighing that
        // follows decides between them.
        if (m_reset_targets.empty()) return 0;
        poses = drawAbout(m_reset_targets, count - n_uniform, r.sampler, *m_free);
    } else if (challenger && !m_challenger->targets.empty()) {
        poses = drawAbout(m_challenger->targets, count - n_uniform, r.sampler, *m_free);
    } else {
        poses = m_sampler.sample(observations, count - n_uniform, rng);
    }
    if (poses.empty()) return 0;  // nothing in view to reset from: keep the set as it is
    while (poses.size() < count) poses.push_back(m_free->drawUniform());
    return mcl.inject(poses);
}

void Localizer::injectAboutLocalTarget(ObjectMcl& mcl, const mrpt::poses::CPose2D* motion) {
    if (!m_local_target) return;
    // The target is the robot pose at the last update: moved by the odometry applied since.
    const mrpt::math::TPose2D target = motion ? (mrpt::poses::CPose2D(*m_local_target) + *motion).asTPose() : *m_local_target;
    m_local_target.reset();
    const auto& r = m_opts.resetting;
    const auto count = static_cast<std::size_t>(std::lround(r.local_fraction * static_cast<double>(mcl.size())));
    if (count == 0) return;
    DetectionPoseSamplerParams spread = r.sampler;
    spread.position_std_m = r.local_position_std_m;
    spread.heading_std_rad = r.local_heading_std_rad;
    const auto poses = drawAbout({Hypothesis{target, 0}}, count, spread, *m_free);
    if (!poses.empty()) mcl.inject(poses);
}

void Localizer::searchHypotheses(double t_s, const std::vector<WeightedObservation>& observations) {
    m_hypotheses.clear();
    m_reset_targets.clear();
    if (!m_opts.search.enabled || observations.empty()) return;
    const auto state = m_monitor.state();
    if (state == LocalizationState::Global && !m_opts.search.while_global) return;
    if (state == LocalizationState::Localized &&
        (!m_opts.search.while_localized || t_s - m_last_search_s < m_opts.search.check_period_s))
        return;
    m_hypotheses = m_search.search(m_fit, observations, m_odometry);
    m_last_search_s = t_s;
    // Particles go only to places that explain the window at least about as well as the estimate
    // does: spending them on worse places pulled a correct set away after a false `lost`.
    m_reset_targets.clear();
    if (m_hypotheses.empty()) return;
    const mrpt::math::TPose2D estimate =
        m_summary ? (mrpt::poses::CPose2D(m_summary->estimate) + m_pending).asTPose() : m_hypotheses.front().pose;
    const double advantage = m_search.rivalAdvantage(m_fit, m_hypotheses, estimate, m_odometry);
    const double best = m_hypotheses.front().log_likelihood;
    const double estimate_ll = std::isnan(advantage) ? best : best - advantage;  // NaN: all near the estimate
    for (const auto& h : m_hypotheses)
        if (h.log_likelihood >= estimate_ll - m_opts.state.rival_margin) m_reset_targets.push_back(h);
}

void Localizer::seedChallenger(const std::vector<WeightedObservation>& observations) {
    auto& ch = *m_challenger;
    ch.places.clear();
    ch.targets.clear();
    if (!m_opts.challenger.hypothesis_search || ch.monitor.state() == LocalizationState::Localized) return;
    ch.places = m_challenger_search.search(m_since_lost, observations, m_odometry);
    // Only the places about as good as the best: the weighing that follows decides between them.
    if (ch.places.empty()) return;
    const double floor = ch.places.front().log_likelihood - m_opts.state.rival_margin;
    for (const auto& h : ch.places)
        if (h.log_likelihood >= floor) ch.targets.push_back(h);
}

void Localizer::update(ObjectMcl& mcl, LocalizationState state, const mrpt::poses::CPose2D* motion,
                       const std::vector<WeightedObservation>& observations, StepRecord& rec) {
    const auto& pf = m_opts.pf;
    std::optional<mrpt::obs::CActionCollection> acts;
    if (motion) acts = makeAction(*motion, m_opts.motion);
    if (pf.PF_algorithm != mrpt::bayes::CParticleFilter::pfStandardProposal) {
        // MRPT's auxiliary filters weigh one pose at a time through the plain Eq. singw.
        mrpt::obs::CSensoryFrame sf;
        for (const auto& o : observations) sf.insert(o.obs);
        mrpt::bayes::CParticleFilter::TParticleFilterStats stats;
        m_pf.executeOn(mcl, acts ? &*acts : nullptr, &sf, &stats);
        rec.ess = stats.ESS_beforeResample * static_cast<double>(mcl.size());
    } else {
        // CParticleFilter::executeOn's steps, with sensor resetting before the weights and the
        // particle count chosen at resampling.
        mcl.predict(acts ? &*acts : nullptr, pf);
        injectFromDetections(mcl, state, observations);
        if (&mcl == m_mcl.get()) injectAboutLocalTarget(mcl, motion);
        const bool own_lost = &mcl == m_mcl.get() && state == LocalizationState::Lost;
        const double detection_power = own_lost ? pf.powFactor * m_opts.experiment.lost_detection_power : pf.powFactor;
        mcl.weigh(observations, detection_power);
        if (m_heading) mcl.weighHeading(*m_heading, observations, detection_power);
        if (m_scan_model && m_pending_scan) {
            mcl.weighScan(*m_scan_model, *m_pending_scan, pf.powFactor);
        }
        mcl.normalizeWeights();
        const double ess = mcl.ESS();
        rec.ess = ess * static_cast<double>(mcl.size());
        rec.injected = mcl.lastInjectedCount();  // recovery and sensor resetting (inject() counts itself)
        if (!pf.adaptiveSampleSize) {
            const std::size_t target = particleTarget(mcl, state);
            if (target != mcl.size())
                mcl.resampleTo(target);
            else if (ess < pf.BETA)
                mcl.resample(pf);
        }
    }
    rec.updated = true;
    rec.detections = mcl.lastDetectionCount();
    rec.pruned = mcl.lastPrunedCount();
}

StepRecord Localizer::step(double t_s, const mrpt::poses::CPose2D& odometry_increment,
                           const mrpt::obs::CSensoryFrame& frame) {
    m_pending = m_pending + odometry_increment;
    m_odometry = m_odometry + odometry_increment;
    std::vector<WeightedObservation> observations =
        m_use_objects ? objectObservations(frame) : std::vector<WeightedObservation>{};
    if (m_scan_model)
        if (auto scan = lastScan(frame)) m_pending_scan = scan;
    const bool consensus = m_heading && m_opts.heading.consensus_tolerance_rad > 0.0;
    std::vector<TrackedDetection> tracked;
    for (auto& o : observations) {
        o.weights = m_novelty.weigh(*o.obs, m_odometry, t_s, consensus ? &tracked : nullptr);
        if (consensus) o.heading_weights = m_yaw_consensus.weigh(*m_heading, *o.obs, tracked, m_odometry, t_s);
        m_fit.add(*m_map, o.obs, m_odometry, t_s, &o.weights);
        if (m_opts.challenger.enabled) {
            m_since_lost.add(*m_map, o.obs, m_odometry, t_s, &o.weights);
            if (m_opts.challenger.min_view_recall > 0) m_views_since_lost.add(*m_map, o.obs, m_odometry, t_s);
        }
    }

    StepRecord rec;
    m_views_asked.reset();
    rec.t_s = t_s;
    const auto& e = m_opts.experiment;
    // Motion trigger (paper: d_xy, d_theta): the first frame, then after enough motion.
    const bool trigger = m_first || m_pending.norm() >= e.update_min_d_xy || std::abs(m_pending.phi()) >= e.update_min_d_phi;
    if (trigger) {
        const auto all = m_skipped.merge(observations, m_pending);
        searchHypotheses(t_s, all);
        const bool no_motion = m_first && m_pending.norm() == 0 && m_pending.phi() == 0;
        update(*m_mcl, m_monitor.state(), no_motion ? nullptr : &m_pending, all, rec);
        if (m_challenger) {
            seedChallenger(all);
            StepRecord ignored;
            update(*m_challenger->mcl, m_challenger->monitor.state(), no_motion ? nullptr : &m_pending, all, ignored);
        }
        if (m_scan_model && m_pending_scan && m_opts.pf.PF_algorithm == mrpt::bayes::CParticleFilter::pfStandardProposal) {
            m_scans_since_lost.add(m_pending_scan, m_odometry);
            m_pending_scan.reset();
        }
        m_pending = mrpt::poses::CPose2D();
        m_first = false;
    } else if (e.keep_skipped_detections) {
        m_skipped.add(observations, m_pending);
    }

    if (trigger || !m_summary) m_summary = summarizeParticles(*m_mcl, e);
    if (trigger) m_summary = keepSpread(*m_mcl, *m_summary);
    // The pose now: the filter's estimate moved by the odometry it has not applied yet.
    auto now = mrpt::poses::CPose2D(m_summary->estimate) + m_pending;
    auto fit = m_fit.evaluate(*m_map, now, m_odometry, t_s);
    if (trigger && !m_hypotheses.empty())
        fit.rival_advantage = m_search.rivalAdvantage(m_fit, m_hypotheses, now.asTPose(), m_odometry);
    // While lost the climb only guards the way back to `localized` (local_entry_margin); the lost
    // set gets no draws about it (the challenger searches).
    const bool lost = m_monitor.state() == LocalizationState::Lost;
    if (trigger && (!lost || m_opts.state.local_entry_margin > 0) && m_fit.size() >= m_opts.state.fit_min_detections) {
        double own = 0;
        const Hypothesis best = m_search.climb(m_fit, now.asTPose(), m_odometry, own);
        fit.local_gain = best.log_likelihood - own;
        fit.local_offset_m = std::hypot(best.pose.x - now.x(), best.pose.y - now.y());
        // Draws only before the filter has localized by its own test: later, a better pose nearby was
        // mostly changed furniture pulling a right set (doc/results-localization.md, 37th session).
        if (!lost && !m_entered_localized && betterPoseNearby(fit, m_opts.state.local_margin)) m_local_target = best.pose;
    }
    if (trigger) {
        const auto before = m_monitor.state();
        const ParticleSummary& s = *m_summary;
        m_monitor.update(s.cluster_weight, std::sqrt(s.cluster_cov(0, 0) + s.cluster_cov(1, 1)), fit,
                         rec.detections > 0);
        if (m_monitor.state() == LocalizationState::Localized && before != LocalizationState::Localized)
            m_entered_localized = true;
        // The detections of the lost hypothesis say nothing about the next one, unless a rival
        // place explained them (then they are what will find it again).
        const bool rival_won = fit.rival_advantage >= m_opts.state.rival_lost_margin;
        if (m_monitor.state() == LocalizationState::Lost && before != LocalizationState::Lost && !rival_won) {
            m_fit.clear();
            m_since_lost.clear();
        }
        if (challenge(t_s, now, rec.detections > 0, before)) {  // the challenger's set is the filter now
            m_novelty.clearUnmapped();  // judged against the estimate it replaced
            now = mrpt::poses::CPose2D(m_summary->estimate) + m_pending;
            fit = m_fit.evaluate(*m_map, now, m_odometry, t_s);
        }
    }
    // This frame's detections judged at a localized estimate that explains the rest of the window:
    // an object it keeps leaving unexplained is not where the map has it (DetectionNovelty).
    const auto judging = m_monitor.state() == LocalizationState::Localized ||
                         (m_opts.novelty.unmapped_while_lost && m_monitor.state() == LocalizationState::Lost);
    if (m_opts.novelty.unmapped_min_detections > 0 && judging &&
        fit.scored >= m_opts.state.fit_min_detections && fit.fraction >= m_opts.novelty.unmapped_min_fit)
        for (const auto& j : m_fit.judgeAt(*m_map, now, m_odometry, t_s, m_opts.novelty.unmapped_tolerance_m,
                                           m_opts.novelty.unmapped_tolerance_rad))
            m_novelty.judge(*j.obs, j.k, j.odometry_pose, j.explained, t_s);
    rec.unmapped_objects = m_novelty.unmappedCount();
    const ParticleSummary& s = *m_summary;
    rec.estimate = now.asTPose();
    rec.mean = s.mean;
    rec.cov = s.cov;
    rec.cluster_cov = s.cluster_cov;
    rec.cluster_weight = s.cluster_weight;
    rec.particles = s.particle_count;
    if (!trigger) rec.ess = s.ess;
    rec.fit = fit.fraction;
    rec.fit_detections = fit.scored;
    rec.rival_advantage = fit.rival_advantage;
    rec.local_gain = fit.local_gain;
    rec.local_offset_m = fit.local_offset_m;
    rec.challenger_particles = m_challenger ? m_challenger->mcl->size() : 0;
    if (m_challenger) {
        rec.challenger_estimate = m_challenger->now;
        rec.challenger_state = m_challenger->monitor.state();
        rec.challenger_fit = m_challenger->fit;
        rec.challenger_lead = m_challenger->lead;
    }
    if (m_views_asked) {
        rec.challenger_views_expected = static_cast<long>(m_views_asked->expected);
        rec.challenger_views_seen = static_cast<long>(m_views_asked->seen);
    }
    rec.state = m_monitor.state();
    return rec;
}

bool Localizer::challenge(double t_s, const mrpt::poses::CPose2D& now, bool had_detections, LocalizationState before) {
    const auto& c = m_opts.challenger;
    const auto state = m_monitor.state();
    if (m_challenger && state == LocalizationState::Localized) m_challenger.reset();  // the `lost` was false
    if (!c.enabled || state != LocalizationState::Lost) return false;
    const std::size_t n = c.particles > 0 ? c.particles : m_opts.experiment.particles_count;
    const auto start = [&] {
        m_challenger.emplace(Challenger{makeFilter(), StateMonitor(m_opts.state), std::nullopt, 1.0, {}, {}});
        resetUniform(*m_challenger->mcl, n);
        ++m_challengers_started;
    };
    if (!m_challenger) {
        if (before != LocalizationState::Lost) {  // updated from the next update on
            m_scans_since_lost.clear();
            m_views_since_lost.clear();
            start();
        }
        return false;
    }
    auto& ch = *m_challenger;
    ch.summary = summarizeParticles(*ch.mcl, m_opts.experiment);
    const auto ch_now = mrpt::poses::CPose2D(ch.summary->estimate) + m_pending;
    auto ch_fit = m_since_lost.evaluate(*m_map, ch_now, m_odometry, t_s);
    // A place elsewhere that explains the window about as well makes it ambiguous: not localized.
    if (!ch.places.empty())
        ch_fit.rival_advantage = m_challenger_search.rivalAdvantage(m_since_lost, ch.places, ch_now.asTPose(), m_odometry);
    ch.unexplained = ch_fit.scored >= m_opts.state.fit_min_detections ? 1.0 - ch_fit.fraction : 1.0;
    ch.now = ch_now.asTPose();
    ch.fit = ch_fit.fraction;
    ch.lead = Challenger::kNone;
    ch.monitor.update(ch.summary->cluster_weight,
                      std::sqrt(ch.summary->cluster_cov(0, 0) + ch.summary->cluster_cov(1, 1)), ch_fit, had_detections);
    if (ch.monitor.state() == LocalizationState::Lost) {  // it settled on a wrong place: search again
        start();
        return false;
    }
    if (ch.monitor.state() != LocalizationState::Localized) return false;
    // Both estimates scored on the detections since `lost` (each detection at the pose of its own
    // frame). The same place is the same position and heading: a challenger turned by more than the
    // search's distinct_heading_rad is elsewhere (a right position with a wrong heading drifts off).
    std::vector<double> log_lik;
    m_since_lost.scorePoses(*m_map, {now.asTPose(), ch_now.asTPose()}, m_odometry, log_lik);
    ch.lead = log_lik[1] - log_lik[0];
    const bool same_place =
        samePlace(ch_now.asTPose(), now.asTPose(), c.agree_distance_m, m_opts.search.distinct_heading_rad);
    const auto current_fit = [&] { return m_since_lost.evaluate(*m_map, now, m_odometry, t_s).fraction; };
    const auto explained_objects = [&] {
        return m_since_lost.explainedObjects(*m_map, ch_now, m_odometry, c.object_radius_m);
    };
    const auto scan_lead = [&]() -> std::optional<double> {  // the LiDAR's say on the way since `lost`
        if (!m_scan_model || m_scans_since_lost.size() == 0) return std::nullopt;
        std::vector<double> scan_log;
        m_scans_since_lost.score(*m_scan_model, {now.asTPose(), ch_now.asTPose()}, m_odometry, scan_log);
        return scan_log[1] - scan_log[0];
    };
    const auto view_recall = [&] {  // what the camera frames since `lost` should have shown there
        m_views_asked = m_views_since_lost.recallAt(*m_map, ch_now, m_odometry, t_s);
        return *m_views_asked;
    };
    if (!challengerTakesOver(c, same_place, ch.lead, current_fit, explained_objects, scan_lead, view_recall))
        return false;
    m_mcl = std::move(ch.mcl);
    m_summary = ch.summary;
    m_monitor = ch.monitor;
    m_challenger.reset();
    ++m_challengers_won;
    return true;
}

}  // namespace simp::localization
