#include <simp/localization/LocalizeApp.h>

#include <mrpt/io/vector_loadsave.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/random/RandomGenerators.h>
#include <simp/eval/Plots.h>
#include <simp/eval/PngFile.h>
#include <simp/eval/Scene3D.h>
#include <simp/localization/RawlogSequence.h>
#include <simp/localization/ScanLikelihood.h>
#include <simp/io/CommandLine.h>
#include <simp/io/StrictNumber.h>
#include <simp/maps/CObjectMap.h>
#include <simp/model/LocalizationMethods.h>
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

/// The method names joined: "simp|edt|..." (sep "|") or "simp, edt, ... or simp+lidar" (sep ", ").
std::string joinedNames(const std::string& sep) {
    const auto& n = model::localizationMethodNames();
    std::string s;
    for (std::size_t k = 0; k < n.size(); ++k) s += (k == 0 ? "" : sep == ", " && k + 1 == n.size() ? " or " : sep) + n[k];
    return s;
}
/// --particles above this is refused: 5e5 particles already take seconds per update (doc/localization.md).
constexpr long long kMaxParticles = 500000;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

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

}  // namespace

maps::CObjectMap::TLikelihoodOptions defaultLikelihoodOptions() {
    maps::CObjectMap::TLikelihoodOptions o;
    o.skip_classes_without_noise = true;
    o.unmodelled_noise_std_m = 0.3;
    return o;
}

std::shared_ptr<maps::CObjectMap> makeObjectMap(const mrpt::config::CConfigFileBase& cfg, const std::string& file) {
    if (!cfg.sectionExists("MetricMap")) {
        auto map = std::make_shared<maps::CObjectMap>();
        map->likelihoodOptions = defaultLikelihoodOptions();
        return map;
    }
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(cfg, "MetricMap");
    mrpt::maps::CMultiMetricMap multi;
    multi.setListOfMaps(inits);
    auto map = multi.mapByClass<maps::CObjectMap>();
    if (!map)
        throw std::invalid_argument(file + ": [MetricMap] creates no semanticObjectMap (set semanticObjectMap_count=1)");
    return map;
}

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

void LocalizeApp::initialize(const std::vector<std::string>& args) {
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    initialize(static_cast<int>(argv.size()), argv.data());
}

io::CommandLine LocalizeApp::commandLine() {
    io::CommandLine c("simp-localize",
                      "Global localization with 3D object detections on a floor plan (MCL, MRPT). Writes OUT/estimate.tum,\n"
                      "OUT/steps.csv, OUT/final_particles.txt, OUT/trajectory.png. See doc/localization.md.");
    c.required("world", "W", "world directory (floorplan.yaml, objects.json)")
        .required("rawlog", "RAWLOG", "input rawlog (Q/sequence.rawlog)")
        .required("out", "O", "output directory")
        .option("config", "INI", "MRPT-style .ini (config_ini/simp.ini)")
        .option("method", "M", "sensor model: " + joinedNames("|") + " (overrides the .ini; lidar: the scans against\n"
                               "the floor plan alone, simp+lidar: times the object model; doc/lidar.md)")
        .option("particles", "N", "particle count, in [1, " + std::to_string(kMaxParticles) + "] (overrides the .ini; default 5000)")
        .option("seed", "S", "random seed, in [0, 2^32) (overrides the .ini; default 0)")
        .option("initial-pose", "POSE", "x,y,phi[,sigma_xy,sigma_phi] (m, rad): track from this pose (default spread 0.2 m,\n"
                                        "0.1 rad) instead of localizing globally")
        .option("gt", "TUM", "ground truth (TUM, Q/groundtruth.tum): drawn in trajectory.png and the 3D scene")
        .option("3dscene", "F", "also write an MRPT .3Dscene (SceneViewer3D): floor plan, objects, trajectories, final particles")
        .flag("quiet", "no progress or log output on stderr")
        .version("0.1");
    return c;
}

void LocalizeApp::initialize(int argc, const char* const* argv) {
    io::CommandLine a = commandLine();
    if (!a.parse(argc, argv, std::cout)) {
        help_requested = true;  // --help / --version printed the text
        return;
    }
    world_dir = a.value("world");
    rawlog_path = a.value("rawlog");
    out_dir = a.value("out");
    config_path = a.value("config");
    show_progress = !a.has("quiet");
    gt_path = a.value("gt");
    scene_path = a.value("3dscene");
    if (!gt_path.empty() && !fs::is_regular_file(gt_path))
        throw std::invalid_argument("simp-localize: --gt '" + gt_path + "' does not exist");

    loadConfig();
    if (a.has("method")) {
        const std::string m = a.value("method");
        if (!model::findLocalizationMethod(m))
            throw std::invalid_argument("simp-localize: unknown --method '" + m + "' (use " + joinedNames(", ") + ")");
        options.experiment.sensor_model = m;
    }
    if (const auto n = a.integer("particles", 1, kMaxParticles)) options.experiment.particles_count = static_cast<std::size_t>(*n);
    if (const auto seed = a.integer("seed", 0, 4294967295LL)) options.experiment.seed = static_cast<std::uint32_t>(*seed);
    if (a.has("initial-pose")) initial_pose = parseInitialPose(a.value("initial-pose"));
}

void LocalizeApp::loadConfig() {
    // Every option struct reads through the StrictIni, so its keys are the known ones: no list here.
    params = std::make_unique<io::StrictIni>(config_path);
    const std::string file = config_path.empty() ? "(no --config)" : config_path;
    try {
        loadLocalizerOptions(*params, options);
        config_notes = reconcilePfOptions(options.pf);
    } catch (const std::exception& e) {
        const std::string m = describeError(e);
        throw std::invalid_argument(m.rfind(file, 0) == 0 ? m : file + ": " + m);
    }
    try {
        m_object_map = makeObjectMap(*params, file);
    } catch (const std::invalid_argument&) {
        throw;
    } catch (const std::exception& e) {
        const std::string m = describeError(e);
        throw std::invalid_argument(m.find(file) != std::string::npos ? m : file + ": [MetricMap]: " + m);
    }
    params->checkUnknown();
    if (options.pf.PF_algorithm == mrpt::bayes::CParticleFilter::pfOptimalProposal)
        throw std::invalid_argument(config_path +
                                    ": [PF_options] PF_algorithm = pfOptimalProposal is not implemented by MRPT's "
                                    "CMonteCarloLocalization2D (use pfStandardProposal)");
}

void LocalizeApp::run() {
    if (help_requested) return;
    std::ostream& out = log ? *log : std::cerr;
    const bool verbose = show_progress || log != nullptr;
    const auto& experiment = options.experiment;
    if (verbose)
        for (const auto& note : config_notes) out << "simp-localize: note: " << config_path << ": " << note << "\n";

    // Inputs.
    if (!fs::is_directory(world_dir)) throw std::runtime_error("world directory '" + world_dir + "' does not exist");
    world::World world = world::loadWorld(world_dir);
    const std::vector<io::StampedPose2D> ground_truth = gt_path.empty() ? std::vector<io::StampedPose2D>{} : io::readTum(gt_path);
    const RawlogSequence seq = loadRawlogSequence(rawlog_path, RawlogTail::AllowTruncated);
    truncated_at_entry = seq.truncated_at_entry;
    if (truncated_at_entry > 0 && verbose)
        out << "simp-localize: warning: rawlog '" << rawlog_path << "' ends with an incomplete entry "
            << truncated_at_entry << " (still being written?): localizing the " << seq.frames.size()
            << " complete frames before it\n";

    // Made by initialize() (so that a bad [MetricMap] is an argument error); a second run() makes it anew.
    std::shared_ptr<maps::CObjectMap> map = m_object_map;
    m_object_map.reset();
    if (!map) map = params ? makeObjectMap(*params, config_path) : std::make_shared<maps::CObjectMap>();
    // The method of --method or [LocalizationExperiment] (checked there); none: the map's object model.
    const std::string& model_name = experiment.sensor_model;
    const model::LocalizationMethod* method = model::findLocalizationMethod(model_name);
    if (!model_name.empty() && !method) throw std::invalid_argument("simp-localize: unknown method '" + model_name + "'");
    const bool with_scans = method && method->uses_scans;
    const bool with_objects = !method || method->object_model;
    // A method without objects (lidar) leaves the map's model: it weighs no detection.
    if (method && method->object_model) map->likelihoodOptions.sensor_model = *method->object_model;
    sensor_model_used = method ? method->name : model::toString(map->likelihoodOptions.sensor_model);
    if (with_scans) {
        std::size_t scans = 0;
        for (const auto& fr : seq.frames) scans += lastScan(*fr.observations) ? 1 : 0;
        if (scans == 0)
            throw std::invalid_argument("simp-localize: --method " + model_name + ": rawlog '" + rawlog_path +
                                        "' holds no mrpt::obs::CObservation2DRangeScan (simulate one with simp-sim "
                                        "sequence --lidar)");
        if (options.pf.PF_algorithm != mrpt::bayes::CParticleFilter::pfStandardProposal)
            throw std::invalid_argument("simp-localize: --method " + model_name +
                                        " needs [PF_options] PF_algorithm = pfStandardProposal");
    }
    map->setData(world.objects);
    if (world.objects.objects.empty()) out << "simp-localize: warning: the object map of '" << world_dir << "' is empty\n";

    // The filter.
    // A fresh generator, not randomize(): MRPT 2.5 keeps the std::normal_distribution's cached
    // second value across randomize(), so a run would depend on the draws of the one before it.
    mrpt::random::getRandomGenerator() = mrpt::random::CRandomGenerator(experiment.seed);
    Localizer localizer(map, world.floorplan, options);
    if (with_scans) {
        const bool objects_in_scan = with_objects && options.lidar.map_objects;
        localizer.setScanModel(
            std::make_shared<ScanLikelihood>(world.floorplan, options.lidar, objects_in_scan ? &world.objects : nullptr),
            with_objects);
    }
    if (initial_pose) {
        const auto& p = *initial_pose;
        try {
            localizer.startAt({p[0], p[1], p[2]}, p[3], p[4]);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(std::string("simp-localize: --initial-pose: ") + e.what() + " of '" +
                                        world_dir + "'");
        }
    } else {
        localizer.startGlobal();
    }
    if (verbose) {
        out << "simp-localize: " << seq.frames.size() << " frames (" << seq.format << ") from '" << rawlog_path
            << "', " << world.objects.objects.size() << " objects, sensor model " << sensor_model_used << ", "
            << experiment.particles_count << " particles, seed " << experiment.seed
            << (initial_pose ? ", tracking from --initial-pose" : ", global localization") << "\n";
    }

    // Outputs, written as the frames are processed.
    fs::create_directories(out_dir);
    const fs::path o(out_dir);
    std::ofstream tum_file((o / "estimate.tum").string()), steps_file((o / "steps.csv").string());
    if (!tum_file || !steps_file) throw std::runtime_error("cannot write into '" + out_dir + "'");
    tum_file << io::tumHeader();
    steps_file << stepsCsvHeader() << "\n";
    steps.clear();
    estimate.clear();
    // The localized/lost state is decided on object detections; without them (lidar) every frame is reported.
    bool reporting = experiment.report_from == ReportFrom::Start || !with_objects;
    const auto t_start = Clock::now();
    auto t_last_progress = t_start;
    const bool tty = isatty(fileno(stderr)) != 0;  // \r-updated line on a terminal, lines otherwise
    for (std::size_t f = 0; f < seq.frames.size(); ++f) {
        const auto t0 = Clock::now();
        const SequenceFrame& frame = seq.frames[f];
        StepRecord rec = localizer.step(frame.t_s, frame.odometry_increment, *frame.observations);
        rec.seconds = secondsSince(t0);
        steps.push_back(rec);
        steps_file << stepsCsvLine(rec);
        reporting = reporting || rec.state == LocalizationState::Localized;
        if (reporting) {
            estimate.push_back({rec.t_s, rec.estimate});
            tum_file << io::tumLine(estimate.back());
        }

        const bool last_frame = f + 1 == seq.frames.size();
        if (show_progress && (secondsSince(t_last_progress) > (tty ? 0.5 : 5.0) || last_frame)) {
            t_last_progress = Clock::now();
            tum_file.flush();
            steps_file.flush();
            const double el = secondsSince(t_start);
            char line[200];
            std::snprintf(line, sizeof(line), "%ssimp-localize: %5.1f%% (%zu/%zu frames, %.1f frames/s, K=%zu, %s)  ",
                          tty ? "\r" : "", 100.0 * (f + 1) / seq.frames.size(), f + 1, seq.frames.size(),
                          (f + 1) / std::max(el, 1e-9), rec.detections, toString(rec.state).c_str());
            std::cerr << line << (last_frame || !tty ? "\n" : "") << std::flush;
        }
    }
    tum_file.close();
    steps_file.close();
    if (!tum_file || !steps_file) throw std::runtime_error("error while writing into '" + out_dir + "'");

    final_particles.clear();
    for (const auto& p : localizer.filter().m_particles) final_particles.push_back(p.d);
    if (experiment.write_particles) writeParticles((o / "final_particles.txt").string(), localizer.filter());
    writePictures(world, ground_truth);
    if (verbose) {
        const auto& last = steps.back();
        out << "simp-localize: final estimate (" << last.estimate.x << ", " << last.estimate.y << ", "
            << last.estimate.phi << "), state " << toString(last.state) << ", in " << secondsSince(t_start)
            << " s; wrote " << o.string() << "/estimate.tum (" << estimate.size() << " poses), steps.csv\n";
        if (estimate.empty())
            out << "simp-localize: warning: the filter never reached state 'localized': estimate.tum is empty "
                   "([LocalizationExperiment] report_from = start writes every frame)\n";
    }
}

void LocalizeApp::writePictures(const world::World& world, const std::vector<io::StampedPose2D>& ground_truth) const {
    if (!options.experiment.write_png && scene_path.empty()) return;
    eval::MapLayers layers;
    layers.floorplan = &world.floorplan;
    layers.objects = &world.objects;
    layers.ground_truth = ground_truth;
    layers.estimate = estimate;
    layers.particles = final_particles;
    if (options.experiment.write_png)
        eval::writePng((fs::path(out_dir) / "trajectory.png").string(), eval::drawTrajectoryMap(layers));
    if (!scene_path.empty()) eval::saveScene(*eval::buildScene(layers), scene_path);
}

std::array<double, 5> parseInitialPose(const std::string& text) {
    std::array<double, 5> v{0, 0, 0, 0.2, 0.1};
    std::size_t count = 0, pos = 0;
    while (pos <= text.size()) {
        const auto comma = text.find(',', pos);
        const std::string item = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
        if (count >= 5) throw std::invalid_argument("simp-localize: --initial-pose '" + text + "': more than 5 numbers");
        const auto x = io::parseFiniteNumber(item);
        if (!x)
            throw std::invalid_argument("simp-localize: --initial-pose '" + text + "': '" + item +
                                        "' is not a finite number (expected x,y,phi[,sigma_xy,sigma_phi])");
        v[count++] = *x;
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    if (count != 3 && count != 5)
        throw std::invalid_argument("simp-localize: --initial-pose '" + text +
                                    "': expected 3 or 5 numbers x,y,phi[,sigma_xy,sigma_phi]");
    if (v[3] < 0 || v[4] < 0 || v[3] > 100 || v[4] > 10)
        throw std::invalid_argument("simp-localize: --initial-pose '" + text +
                                    "': sigma_xy must be in [0, 100] m and sigma_phi in [0, 10] rad");
    return v;
}

}  // namespace simp::localization
