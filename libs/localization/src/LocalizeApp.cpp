#include <simp/localization/LocalizeApp.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/io/vector_loadsave.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/localization/FreeSpace.h>
#include <simp/localization/ObjectMcl.h>
#include <simp/localization/RawlogSequence.h>
#include <simp/localization/SkippedDetections.h>
#include <simp/localization/TrajectoryImage.h>
#include <simp/maps/CObjectMap.h>
#include <simp/world/World.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace simp::localization {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// The object map: from the .ini's [MetricMap] (MRPT's TSetOfMetricMapInitializers, which can
/// create "semanticObjectMap" / "simp::maps::CObjectMap"), else one with default options.
std::shared_ptr<maps::CObjectMap> makeObjectMap(const mrpt::config::CConfigFileBase& cfg, const std::string& file) {
    if (!cfg.sectionExists("MetricMap")) return std::make_shared<maps::CObjectMap>();
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(cfg, "MetricMap");
    mrpt::maps::CMultiMetricMap multi;
    multi.setListOfMaps(inits);
    auto map = multi.mapByClass<maps::CObjectMap>();
    if (!map)
        throw std::invalid_argument(file + ": [MetricMap] creates no semanticObjectMap (set semanticObjectMap_count=1)");
    return map;
}

/// The action of one filter step: the odometry increment with the [MotionModel] noise.
mrpt::obs::CActionCollection makeAction(const mrpt::poses::CPose2D& increment, const MotionModelOptions& motion) {
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(increment, motion.mrpt_options);
    mrpt::obs::CActionCollection acts;
    acts.insert(mv);
    return acts;
}

void writeParticles(const std::string& path, const mrpt::slam::CMonteCarloLocalization2D& pdf) {
    std::ofstream f(path);
    if (!f) throw std::runtime_error("cannot write '" + path + "'");
    f << "# x_m y_m phi_rad log_weight\n";
    char line[128];
    for (const auto& p : pdf.m_particles) {
        std::snprintf(line, sizeof(line), "%.6f %.6f %.6f %.6f\n", p.d.x, p.d.y, p.d.phi, p.log_w);
        f << line;
    }
    if (!f) throw std::runtime_error("error while writing '" + path + "'");
}

/// TCLAP output that prints --help to stdout but keeps a parse error for the exception.
class RecordingOutput : public TCLAP::StdOutput {
   public:
    void failure(TCLAP::CmdLineInterface& /*c*/, TCLAP::ArgException& e) override {
        error = e.error() + (e.argId().empty() ? "" : " (" + e.argId() + ")");
    }
    std::string error;
};

}  // namespace

std::string describeError(const std::exception& e) {
    const std::string all = mrpt::exception_to_str(e);
    if (all.find("Message:") == std::string::npos) return e.what();
    std::istringstream in(all);
    std::string out;
    for (std::string line; std::getline(in, line);) {
        const auto pos = line.find("Message:");
        if (pos == std::string::npos) continue;
        std::string m = line.substr(pos + 8);
        m.erase(0, m.find_first_not_of(' '));
        if (m.empty() || m.rfind("Exception while parsing", 0) == 0) continue;
        out += (out.empty() ? "" : ": ") + m;
    }
    return out.empty() ? all : out;
}

mrpt::bayes::CParticleFilter::TParticleFilterOptions LocalizeApp::defaultPfOptions() {
    mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
    o.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
    o.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
    o.adaptiveSampleSize = false;
    o.BETA = 0.5;
    o.sampleSize = 1;
    return o;
}

void LocalizeApp::initialize(const std::vector<std::string>& args) {
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    initialize(static_cast<int>(argv.size()), argv.data());
}

void LocalizeApp::initialize(int argc, const char* const* argv) {
    TCLAP::CmdLine cmd(
        "simp-localize: global localization with 3D object detections on a floor plan (MCL, MRPT). "
        "Writes OUT/estimate.tum, OUT/steps.csv, OUT/final_particles.txt, OUT/trajectory.png. "
        "See doc/localization.md.",
        ' ', "0.1");
    TCLAP::ValueArg<std::string> a_world("", "world", "world directory (floorplan.yaml, objects.json); required", false, "", "W", cmd);
    TCLAP::ValueArg<std::string> a_rawlog("", "rawlog", "input rawlog (Q/sequence.rawlog); required", false, "", "RAWLOG", cmd);
    TCLAP::ValueArg<std::string> a_out("", "out", "output directory; required", false, "", "O", cmd);
    TCLAP::ValueArg<std::string> a_config("", "config", "MRPT-style .ini (config_ini/simp.ini)", false, "", "INI", cmd);
    TCLAP::ValueArg<std::string> a_method("", "method", "sensor model: simp|edt|d|o (overrides the .ini)", false, "",
                                          "M", cmd);
    TCLAP::ValueArg<long long> a_particles("", "particles", "particle count (overrides the .ini; default 5000)", false,
                                           0, "N", cmd);
    TCLAP::ValueArg<long long> a_seed("", "seed", "random seed (overrides the .ini; default 0)", false, 0, "S", cmd);
    TCLAP::SwitchArg a_quiet("", "quiet", "no progress or log output on stderr", cmd, false);
    RecordingOutput recorder;
    cmd.setOutput(&recorder);

    std::vector<const char*> args;
    for (int i = 0; i < argc; ++i) args.push_back(argv[i]);
    if (args.empty()) args.push_back("simp-localize");
    if (!cmd.parse(static_cast<int>(args.size()), args.data())) {
        if (!recorder.error.empty()) throw std::invalid_argument("simp-localize: " + recorder.error + "; see --help");
        help_requested = true;  // --help / --version printed the text
        return;
    }
    for (const auto* a : {&a_world, &a_rawlog, &a_out})
        if (!a->isSet()) throw std::invalid_argument("simp-localize: missing required option --" + a->getName() + "; see --help");
    world_dir = a_world.getValue();
    rawlog_path = a_rawlog.getValue();
    out_dir = a_out.getValue();
    config_path = a_config.getValue();
    show_progress = !a_quiet.getValue();

    loadConfig();
    if (a_method.isSet()) {
        const std::string m = a_method.getValue();
        if (std::find(sensorModelNames().begin(), sensorModelNames().end(), m) == sensorModelNames().end())
            throw std::invalid_argument("simp-localize: unknown --method '" + m + "' (use simp, edt, d or o)");
        experiment.sensor_model = m;
    }
    if (a_particles.isSet()) {
        if (a_particles.getValue() <= 0) throw std::invalid_argument("simp-localize: --particles must be > 0");
        experiment.particles_count = static_cast<std::size_t>(a_particles.getValue());
    }
    if (a_seed.isSet()) {
        if (a_seed.getValue() < 0 || a_seed.getValue() > 4294967295LL)
            throw std::invalid_argument("simp-localize: --seed must be in [0, 2^32)");
        experiment.seed = static_cast<std::uint32_t>(a_seed.getValue());
    }
}

void LocalizeApp::loadConfig() {
    if (config_path.empty()) return;
    if (!fs::is_regular_file(config_path)) throw std::invalid_argument("config file '" + config_path + "' does not exist");
    params.setContent(mrpt::io::file_get_contents(config_path));
    validateIniKeys(params, config_path);
    try {
        experiment.loadFromConfigFile(params, "LocalizationExperiment");
        motion.loadFromConfigFile(params, "MotionModel");
        if (params.sectionExists("PF_options")) pf_options.loadFromConfigFile(params, "PF_options");
    } catch (const std::exception& e) {
        throw std::invalid_argument(config_path + ": " + describeError(e));
    }
    if (pf_options.PF_algorithm == mrpt::bayes::CParticleFilter::pfOptimalProposal)
        throw std::invalid_argument(config_path +
                                    ": [PF_options] PF_algorithm = pfOptimalProposal is not implemented by MRPT's "
                                    "CMonteCarloLocalization2D (use pfStandardProposal)");
}

void LocalizeApp::run() {
    if (help_requested) return;
    std::ostream& out = log ? *log : std::cerr;
    const bool verbose = show_progress || log != nullptr;

    // Inputs.
    if (!fs::is_directory(world_dir)) throw std::runtime_error("world directory '" + world_dir + "' does not exist");
    world::World world = world::loadWorld(world_dir);
    const RawlogSequence seq = loadRawlogSequence(rawlog_path);

    std::shared_ptr<maps::CObjectMap> map;
    try {
        map = makeObjectMap(params, config_path);
    } catch (const std::invalid_argument&) {
        throw;
    } catch (const std::exception& e) {
        throw std::invalid_argument(config_path + ": [MetricMap]: " + describeError(e));
    }
    if (!experiment.sensor_model.empty())
        map->likelihoodOptions.sensor_model = maps::parseSensorModelType(experiment.sensor_model);
    sensor_model_used = maps::toString(map->likelihoodOptions.sensor_model);
    map->setData(world.objects);
    if (world.objects.objects.empty()) out << "simp-localize: warning: the object map of '" << world_dir << "' is empty\n";

    // The filter.
    mrpt::random::getRandomGenerator().randomize(experiment.seed);
    auto free_space = std::make_shared<FreeSpace>(world.floorplan, experiment.free_cells_threshold);
    ObjectMcl mcl(map);
    mcl.options.KLD_params.loadFromConfigFile(params, "KLD_options");
    mcl.prune_outside_free_space = experiment.prune_outside_free_space;
    mcl.prune_keeps_weight = experiment.prune_keeps_weight;
    mcl.singw_per_frame = experiment.singw_per_frame;
    mcl.recovery_alpha_slow = experiment.recovery_alpha_slow;
    mcl.recovery_alpha_fast = experiment.recovery_alpha_fast;
    mcl.setFreeSpace(free_space);
    mcl.resetUniformFreeSpace(&world.floorplan, experiment.free_cells_threshold,
                              static_cast<int>(experiment.particles_count));
    mrpt::bayes::CParticleFilter pf;
    pf.m_options = pf_options;

    if (verbose) {
        out << "simp-localize: " << seq.frames.size() << " frames (" << seq.format << ") from '" << rawlog_path
            << "', " << world.objects.objects.size() << " objects, sensor model " << sensor_model_used << ", "
            << experiment.particles_count << " particles over " << free_space->freeArea() << " m^2 free, seed "
            << experiment.seed << "\n";
    }

    steps.clear();
    estimate.clear();
    mrpt::poses::CPose2D pending;  // odometry not yet applied to the particles
    SkippedDetections skipped;     // detections of the frames since the last update
    const auto t_start = Clock::now();
    auto t_last_progress = t_start;
    const bool tty = isatty(fileno(stderr)) != 0;  // \r-updated line on a terminal, lines otherwise
    for (std::size_t f = 0; f < seq.frames.size(); ++f) {
        const auto t0 = Clock::now();
        const SequenceFrame& frame = seq.frames[f];
        pending = pending + frame.odometry_increment;
        // Motion trigger (paper: d_xy, d_theta): the first frame, then after enough motion.
        const bool trigger = f == 0 || pending.norm() >= experiment.update_min_d_xy ||
                             std::abs(pending.phi()) >= experiment.update_min_d_phi;
        StepRecord rec;
        rec.t_s = frame.t_s;
        if (trigger) {
            mrpt::bayes::CParticleFilter::TParticleFilterStats stats;
            const auto sf = skipped.merge(frame.observations, pending);
            if (f == 0 && pending.norm() == 0 && pending.phi() == 0) {
                pf.executeOn(mcl, nullptr, sf.get(), &stats);
            } else {
                const auto acts = makeAction(pending, motion);
                pf.executeOn(mcl, &acts, sf.get(), &stats);
            }
            pending = mrpt::poses::CPose2D();
            rec.updated = true;
            rec.detections = mcl.lastDetectionCount();
            rec.pruned = mcl.lastPrunedCount();
            rec.ess = stats.ESS_beforeResample * static_cast<double>(mcl.size());
        } else if (experiment.keep_skipped_detections) {
            skipped.add(*frame.observations, pending);
        }
        const ParticleSummary s = summarizeParticles(mcl, experiment);
        // The pose now: the filter's estimate moved by the odometry it has not applied yet.
        rec.estimate = (mrpt::poses::CPose2D(s.estimate) + pending).asTPose();
        rec.mean = s.mean;
        rec.cov = s.cov;
        rec.cluster_weight = s.cluster_weight;
        rec.particles = s.particle_count;
        if (!trigger) rec.ess = s.ess;
        rec.seconds = secondsSince(t0);
        steps.push_back(rec);
        estimate.push_back({rec.t_s, rec.estimate});

        const bool last_frame = f + 1 == seq.frames.size();
        if (show_progress && (secondsSince(t_last_progress) > (tty ? 0.5 : 5.0) || last_frame)) {
            t_last_progress = Clock::now();
            const double el = secondsSince(t_start);
            char line[160];
            std::snprintf(line, sizeof(line), "%ssimp-localize: %5.1f%% (%zu/%zu frames, %.1f frames/s, K=%zu)  ",
                          tty ? "\r" : "",
                          100.0 * (f + 1) / seq.frames.size(), f + 1, seq.frames.size(), (f + 1) / std::max(el, 1e-9),
                          rec.detections);
            std::cerr << line << (last_frame || !tty ? "\n" : "") << std::flush;
        }
    }

    final_particles.clear();
    for (const auto& p : mcl.m_particles) final_particles.push_back(p.d);

    // Outputs.
    fs::create_directories(out_dir);
    const std::string o = (fs::path(out_dir)).string();
    io::writeTum((fs::path(o) / "estimate.tum").string(), estimate);
    writeStepsCsv((fs::path(o) / "steps.csv").string(), steps);
    if (experiment.write_particles) writeParticles((fs::path(o) / "final_particles.txt").string(), mcl);
    if (experiment.write_png) {
        std::vector<mrpt::math::TPose2D> traj;
        for (const auto& e : estimate) traj.push_back(e.pose);
        writeTrajectoryPng((fs::path(o) / "trajectory.png").string(), world.floorplan, world.objects, traj,
                           final_particles);
    }
    if (verbose) {
        const auto& last = steps.back().estimate;
        out << "simp-localize: final estimate (" << last.x << ", " << last.y << ", " << last.phi << ") in "
            << secondsSince(t_start) << " s; wrote " << o << "/estimate.tum, steps.csv\n";
    }
}

}  // namespace simp::localization
