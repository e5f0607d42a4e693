#include <simp/demo/DemoApp.h>
#include <simp/eval/KidnapMetrics.h>
#include <simp/eval/MapMetrics.h>
#include <simp/eval/PngFile.h>
#include <simp/eval/Plots.h>
#include <simp/eval/TrajectoryMetrics.h>
#include <simp/io/StrictIni.h>
#include <simp/io/CommandLine.h>
#include <simp/io/OptionTable.h>
#include <simp/io/Tum.h>
#include <simp/localization/LocalizeApp.h>
#include <simp/mapping/MapApp.h>
#include <simp/mapping/MappingOptions.h>
#include <simp/model/LocalizationMethods.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/sim/Office.h>
#include <simp/sim/Sequence.h>
#include <simp/sim/Trajectory.h>
#include <simp/world/World.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace simp::demo {
namespace {

/// Command-line ranges: --seed any 63-bit value; --particles as simp-localize's (5e5: seconds per update).
constexpr std::int64_t kMaxSeed = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kMaxParticles = 500000;

/// The .ini files are checked before the minutes of simulation: the same StrictIni policy the
/// localization and mapping apps apply (unknown keys/sections, malformed values name file and key).
void checkLocalizationConfig(const std::string& path) {
    localization::LocalizeApp probe;  // initialize() reads and checks the .ini, run() is not called
    probe.initialize({"simp-localize", "--world", ".", "--rawlog", ".", "--out", ".", "--config", path, "--quiet"});
}

void checkMappingConfig(const std::string& path) {
    mapping::MappingOptions opts;
    io::StrictIni(path).loadChecked([&](const io::StrictIni& ini) { opts.loadFromConfigFile(ini, "mapping"); });
}

class Stopwatch {
   public:
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    }

   private:
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

std::string projectFile(const std::string& relative) {
    const std::string path = std::string(SIMP_SOURCE_DIR) + "/" + relative;
    return fs::exists(path) ? path : std::string();
}

/// "simp|edt|d|o": the methods the demo runs, the object models alone.
std::string objectModelChoices() {
    std::string s;
    for (const auto& m : model::sensorModelTypeNames()) s += (s.empty() ? "" : "|") + m;
    return s;
}

}  // namespace

std::string DemoOptions::defaultLocalizationConfig() { return projectFile("config_ini/simp.ini"); }
std::string DemoOptions::defaultMappingConfig() { return projectFile("config_ini/mapping.ini"); }

io::CommandLine DemoApp::commandLine() {
    io::CommandLine c("simp-demo",
                      "Runs the whole pipeline on the built-in office world (no external data): builds the world,\n"
                      "simulates a mapping run, builds the object map from posed detections, simulates localization\n"
                      "runs with long-term changes (0 %, 15 %, 30 %, ...), localizes globally in the built map with the\n"
                      "paper's sensor model, prints success / convergence time / ATE per run and writes PNGs to DIR.\n"
                      "A kidnapped run K1 (15 % changes, teleported at half its duration) follows unless --no-kidnap:\n"
                      "lost within 5 s, localized again within 20 s, then tracked.");
    c.option("out", "DIR", "output directory (default demo_out)")
        .option("seed", "S", "random seed of the world and the sequences")
        .option("rooms", "N", "rooms of the built-in office, in [2, 2000]")
        .option("particles", "N", "particle count, in [10, 500000]")
        .option("method", objectModelChoices(), "sensor model")
        .option("runs", "N", "localization runs with 0 %, 15 %, 30 %, ... changes, in [1, 10]")
        .option("mapping-duration", "SEC", "duration of the mapping run")
        .unit("s")
        .option("duration", "SEC", "duration of each localization run")
        .unit("s")
        .option("config", "LOCALIZATION.ini", "localization .ini (default config_ini/simp.ini)")
        .option("mapping-config", "MAPPING.ini", "mapping .ini (default config_ini/mapping.ini)")
        .flag("no-kidnap", "no kidnapped run K1");
    return c;
}

std::string DemoApp::usage() { return commandLine().help(); }

bool DemoApp::initialize(const std::vector<std::string>& args, std::ostream& out) {
    io::CommandLine c = commandLine();
    if (!c.parse(args, out)) return false;
    if (c.has("out")) options.out_dir = c.value("out");
    if (auto v = c.integer("seed", 0, kMaxSeed)) options.seed = static_cast<std::uint64_t>(*v);
    if (auto v = c.integer("rooms", 2, 2000)) options.rooms = static_cast<int>(*v);
    if (auto v = c.integer("particles", 10, kMaxParticles)) options.particles = static_cast<int>(*v);
    if (c.has("method")) {
        options.method = c.value("method");
        // the object models only (the demo's sequences carry no scans)
        const auto& models = model::sensorModelTypeNames();
        if (std::find(models.begin(), models.end(), options.method) == models.end())
            throw std::invalid_argument("option --method: '" + options.method + "' is not " + io::option_text::choices(models));
    }
    if (auto v = c.integer("runs", 1, 10)) {
        options.changes.clear();
        for (int k = 0; k < static_cast<int>(*v); ++k) options.changes.push_back(0.15 * k);
    }
    if (auto v = c.number("mapping-duration", 1, sim::kMaxDuration_s)) options.mapping_duration_s = *v;
    if (auto v = c.number("duration", 1, sim::kMaxDuration_s)) options.localization_duration_s = *v;
    if (c.has("config")) {
        options.localization_config = c.value("config");
        checkLocalizationConfig(options.localization_config);
    }
    if (c.has("no-kidnap")) options.kidnap_run = false;
    if (c.has("mapping-config")) {
        options.mapping_config = c.value("mapping-config");
        checkMappingConfig(options.mapping_config);
    }
    return true;
}

void DemoApp::run(std::ostream& out) {
    const Stopwatch total;
    const fs::path root(options.out_dir);
    fs::create_directories(root);
    const std::string world_dir = (root / "world").string();
    const std::string map_dir = (root / "map").string();

    // 1. The built-in office: the ground truth.
    out << "[1/6] Generating the built-in office (" << options.rooms << " rooms, seed " << options.seed << ")\n";
    sim::OfficeParams office;
    office.rooms = options.rooms;
    const world::World truth = sim::generateOffice(office, options.seed);
    world::saveWorld(truth, world_dir);
    out << "      " << truth.objects.objects.size() << " objects -> " << world_dir << "\n";

    // 2. Mapping run with known poses, then the paper's mapping.
    out << "[2/6] Simulating a mapping run (" << options.mapping_duration_s << " s) and building the object map\n";
    sim::SimParams mapping_run;
    mapping_run.duration_s = options.mapping_duration_s;
    mapping_run.trajectory.coverage = true;  // a mapping run visits every room
    mapping_run.progress = false;
    const std::string mapping_seq = (root / "mapping_run").string();
    sim::simulateSequence(truth, mapping_run, options.seed + 1000, mapping_seq);
    mapping::MapApp mapper;
    std::ostringstream mapping_log;
    mapper.log = &mapping_log;
    mapping::MapAppArgs margs;
    margs.world_dir = world_dir;
    margs.rawlog_path = mapping_seq + "/sequence.rawlog";
    margs.poses_path = mapping_seq + "/groundtruth.tum";
    margs.out_dir = map_dir;
    margs.config_path = options.mapping_config;
    mapper.initialize(margs);
    mapper.run();
    const world::World built = world::loadWorld(map_dir);
    out << "      " << built.objects.objects.size() << " objects built from " << mapper.framesMapped()
        << " camera frames -> " << map_dir << "\n";

    // 3. Map quality against the ground truth, over the paper's Table I classes (config_ini/batch.ini's
    //    `classes`); the doors the mapper also builds are for localization, not part of Table I.
    eval::MapMatchParams match;
    for (const auto& name : truth.objects.class_names)
        if (obs::classIndexOf(obs::tableIClassNames(), name) >= 0) match.classes.push_back(name);
    const auto map_metrics = eval::evaluateMap(truth.objects, built.objects, match);
    map_iou = map_metrics.iou;
    map_precision = map_metrics.precision;
    map_recall = map_metrics.recall;
    out << std::fixed << std::setprecision(2) << "[3/6] Built map vs ground truth: IoU " << map_iou << ", precision "
        << map_precision << ", recall " << map_recall << "\n";
    eval::writePng((root / "object_map.png").string(), eval::drawObjectMap(built));
    eval::writePng((root / "map_evaluation.png").string(), eval::drawMapEvaluation(truth, built, map_metrics));

    // 4. Localization runs in changed worlds, on the built map.
    runs.clear();
    for (std::size_t k = 0; k < options.changes.size(); ++k) {
        DemoRun r;
        r.name = "R" + std::to_string(k + 1);
        r.changes = options.changes[k];
        out << "[4/6] " << r.name << ": simulating " << options.localization_duration_s << " s with "
            << static_cast<int>(100 * r.changes + 0.5) << " % changed objects, localizing with "
            << options.particles << " particles (" << options.method << ")\n";
        sim::SimParams loc_run;
        loc_run.duration_s = options.localization_duration_s;
        loc_run.progress = false;
        loc_run.changes.fraction = r.changes;
        const std::string seq = (root / ("seq_" + r.name)).string();
        sim::simulateSequence(truth, loc_run, options.seed + 2000 + k, seq);

        const std::string est_dir = (root / ("loc_" + r.name)).string();
        localize(map_dir, seq, est_dir, options.seed + 3000 + k);
        const auto gt = io::readTum(seq + "/groundtruth.tum");
        const auto est = io::readTum(est_dir + "/estimate.tum");
        const eval::TrajMetricsParams params;
        if (est.empty()) {  // never localized: a failed run, nothing to measure
            r.duration_s = gt.empty() ? 0.0 : gt.back().t_s - gt.front().t_s;
            runs.push_back(r);
            continue;
        }
        const auto m = eval::evaluateTrajectory(gt, est, params);
        r.success = m.success;
        r.converged = m.converged;
        r.convergence_time_s = m.convergence_time_s.value_or(-1.0);
        r.ate_trans_m = m.ate_trans_m.value_or(-1.0);
        r.ate_rot_rad = m.ate_rot_rad.value_or(-1.0);
        r.duration_s = m.duration_s;
        eval::writePng((root / (r.name + "_trajectory.png")).string(),
                 eval::drawTrajectoryFigure(gt, est, m, params, &built));
        runs.push_back(r);
    }

    // 5. A kidnapped robot.
    kidnap_runs.clear();
    if (options.kidnap_run) kidnap_runs.push_back(runKidnapped(root, map_dir, truth, built, out));

    // 6. The tables.
    std::string table = resultsTable(runs);
    if (!kidnap_runs.empty()) table += "\nKidnapped robot:\n\n" + kidnapTable(kidnap_runs);
    std::ofstream((root / "results.md").string())
        << "# simp-demo results\n\nBuilt map vs ground truth: IoU " << map_iou << ", precision " << map_precision
        << ", recall " << map_recall << "\n\n"
        << table;
    out << "[6/6] Results (also in " << (root / "results.md").string() << ")\n\n" << table << "\n";
    out << "PNGs: " << (root / "object_map.png").string() << ", " << (root / "map_evaluation.png").string()
        << ", " << (root / "R1_trajectory.png").string() << " ...\n";
    out << "Done in " << std::setprecision(1) << total.seconds() << " s.\n";
}

localization::LocalizeApp DemoApp::localize(const std::string& map_dir, const std::string& seq_dir,
                                            const std::string& est_dir, std::uint64_t seed) const {
    localization::LocalizeApp loc;
    std::vector<std::string> args{"simp-localize", "--world", map_dir, "--rawlog", seq_dir + "/sequence.rawlog", "--out", est_dir,
                                  "--method", options.method, "--particles", std::to_string(options.particles),
                                  "--seed", std::to_string(seed)};
    if (!options.localization_config.empty()) {
        args.push_back("--config");
        args.push_back(options.localization_config);
    }
    loc.initialize(args);
    loc.show_progress = false;
    std::ostringstream log;
    loc.log = &log;
    loc.run();
    loc.log = nullptr;
    return loc;
}

DemoKidnapRun DemoApp::runKidnapped(const fs::path& root, const std::string& map_dir, const world::World& truth,
                                    const world::World& built, std::ostream& out) const {
    DemoKidnapRun r;
    r.kidnap_at_s = 0.5 * options.localization_duration_s;
    out << "[5/6] " << r.name << ": simulating " << options.localization_duration_s << " s with "
        << static_cast<int>(100 * r.changes + 0.5) << " % changed objects and a kidnap at " << r.kidnap_at_s
        << " s, localizing\n";
    sim::SimParams run;
    run.duration_s = options.localization_duration_s;
    run.progress = false;
    run.changes.fraction = r.changes;
    run.kidnap_at_s = r.kidnap_at_s;
    const std::string seq = (root / ("seq_" + r.name)).string();
    const auto summary = sim::simulateSequence(truth, run, options.seed + 2500, seq);
    const auto loc = localize(map_dir, seq, (root / ("loc_" + r.name)).string(), options.seed + 3500);
    if (!summary.kidnap) return r;  // no pose qualified for the teleport (tiny worlds): a failed run
    std::vector<eval::StateSample> states;
    for (const auto& s : loc.steps) {
        eval::StateSample e;
        e.t_s = s.t_s;
        e.estimate = s.estimate;
        e.state = s.state == localization::LocalizationState::Localized ? eval::StateSample::State::Localized
                  : s.state == localization::LocalizationState::Lost    ? eval::StateSample::State::Lost
                                                                        : eval::StateSample::State::Global;
        states.push_back(e);
    }
    const auto gt = io::readTum(seq + "/groundtruth.tum");
    const auto m = eval::evaluateKidnap(gt, states, loc.estimate, summary.kidnap->t_s);
    r.lost_after_s = m.lost_after_s.value_or(-1.0);
    r.relocalized_after_s = m.relocalized_after_s.value_or(-1.0);
    if (m.after && m.after->success) {
        r.after_ate_trans_m = m.after->ate_trans_m.value_or(-1.0);
        r.after_ate_rot_rad = m.after->ate_rot_rad.value_or(-1.0);
    }
    r.success = m.success;
    if (!loc.estimate.empty()) {
        const auto whole = eval::evaluateTrajectory(gt, loc.estimate, eval::TrajMetricsParams());
        eval::writePng((root / (r.name + "_trajectory.png")).string(),
                 eval::drawTrajectoryFigure(gt, loc.estimate, whole, eval::TrajMetricsParams(), &built));
    }
    return r;
}

std::string kidnapTable(const std::vector<DemoKidnapRun>& runs) {
    std::ostringstream s;
    s << std::fixed;
    s << "| run | changed objects | kidnap at (s) | lost after (s) | localized again after (s) | ATE after (m) | ATE after (rad) | success |\n";
    s << "|---|---|---|---|---|---|---|---|\n";
    const auto cell = [](double v, int decimals) {
        if (v < 0) return std::string("—");
        std::ostringstream c;
        c << std::fixed << std::setprecision(decimals) << v;
        return c.str();
    };
    for (const auto& r : runs)
        s << "| " << r.name << " | " << cell(100 * r.changes, 0) << " % | " << cell(r.kidnap_at_s, 1) << " | "
          << cell(r.lost_after_s, 1) << " | " << cell(r.relocalized_after_s, 1) << " | "
          << cell(r.success ? r.after_ate_trans_m : -1, 3) << " | " << cell(r.success ? r.after_ate_rot_rad : -1, 3)
          << " | " << (r.success ? "yes" : "no") << " |\n";
    return s.str();
}

std::string resultsTable(const std::vector<DemoRun>& runs) {
    // A failed run has no convergence time and no ATE to report: a transient convergence
    // before a divergence, or an error measured after it, would read as a result.
    std::ostringstream s;
    s << std::fixed;
    s << "| run | changed objects | success | convergence time (s) | ATE (m) | ATE (rad) | duration (s) |\n";
    s << "|---|---|---|---|---|---|---|\n";
    const auto cell = [&](double v, int decimals) {
        std::ostringstream c;
        c << std::fixed << std::setprecision(decimals) << v;
        return c.str();
    };
    for (const auto& r : runs) {
        const bool ok = r.success;
        s << "| " << r.name << " | " << std::setprecision(0) << 100 * r.changes << " % | "
          << (ok ? "yes" : r.converged ? "failed (diverged)" : "failed (never converged)") << " | "
          << (ok && r.convergence_time_s >= 0 ? cell(r.convergence_time_s, 1) : "—") << " | "
          << (ok && r.ate_trans_m >= 0 ? cell(r.ate_trans_m, 3) : "—") << " | "
          << (ok && r.ate_rot_rad >= 0 ? cell(r.ate_rot_rad, 3) : "—") << " | " << std::setprecision(1) << r.duration_s
          << " |\n";
    }
    return s.str();
}

}  // namespace simp::demo
