/// The sub-commands of EvalApp (EvalApp.cpp holds the command-line parsing).
#include <simp/io/StrictIni.h>
#include <simp/eval/BatchConfig.h>
#include <simp/eval/BatchFigures.h>
#include <simp/eval/BatchMaps.h>
#include <simp/eval/BatchRunner.h>
#include <simp/eval/BatchTables.h>
#include <simp/eval/ChangeMetrics.h>
#include <simp/eval/EvalApp.h>
#include <simp/eval/MapMetrics.h>
#include <simp/eval/Plots.h>
#include <simp/eval/PngFile.h>
#include <simp/eval/Report.h>
#include <simp/world/World.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace fs = std::filesystem;

namespace simp::eval {
namespace {

void requireFile(const std::string& path, const std::string& what) {
    if (!fs::is_regular_file(path)) throw std::runtime_error(what + " '" + path + "': file not found");
}

void requireDir(const std::string& path, const std::string& what) {
    if (!fs::is_directory(path)) throw std::runtime_error(what + " '" + path + "': directory not found");
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream f(path);
    if (!f) throw std::runtime_error("cannot write '" + path.string() + "'");
    f << text;
}

/// Writes a figure to `png` and names it on `out` ("figure: <png>").
void writeFigure(const std::string& png, const cv::Mat& image, std::ostream& out) {
    writePng(png, image);
    out << "figure: " << png << "\n";
}

}  // namespace

int EvalApp::runTraj(std::ostream& out) {
    const std::string gt_path = required("--gt"), est_path = required("--est");
    requireFile(gt_path, "ground-truth trajectory");
    requireFile(est_path, "estimated trajectory");
    TrajMetricsParams p;
    if (has("--config")) {
        const io::StrictIni ini(value("--config"));
        ini.loadChecked([&](const io::StrictIni& c) { loadTrajMetricsParams(c, p); }, {"batch", "map_metrics"});
    }
    p.max_trans_m = number("--max-trans", p.max_trans_m, 1e-6, 1e3);
    p.max_rot_rad = number("--max-rot", p.max_rot_rad, 1e-6, 2 * M_PI);
    p.max_outside_s = number("--max-outside", p.max_outside_s, 0, 1e6);
    p.convergence_fraction = number("--fraction", p.convergence_fraction, 1e-6, 1);
    if (!(p.max_trans_m > 0 && p.max_rot_rad > 0 && p.max_outside_s >= 0 && p.convergence_fraction > 0 &&
          p.convergence_fraction <= 1))
        throw std::invalid_argument(
            "simp-eval traj: bounds must be positive and the convergence fraction in (0, 1]");

    const TrajectoryFiles files = readTrajectoryFiles(gt_path, est_path);
    const TrajMetrics m = evaluateTrajectory(files, p);
    out << "trajectory evaluation: " << est_path << " against " << gt_path << "\n" << trajSummaryText(m, p);
    if (has("--png")) {
        world::World w;
        const bool with_world = has("--world");
        if (with_world) {
            requireDir(value("--world"), "world");
            w = world::loadWorld(value("--world"));
        }
        writeFigure(value("--png"),
                    drawTrajectoryFigure(files.ground_truth, files.estimate, m, p, with_world ? &w : nullptr), out);
    }
    if (has("--json")) out << toJson(m).dump() << "\n";
    return 0;
}

int EvalApp::runMap(std::ostream& out) {
    const std::string gt_dir = required("--gt"), map_dir = required("--map");
    requireDir(gt_dir, "ground-truth world");
    requireDir(map_dir, "map world");
    MapMatchParams p;
    if (has("--config")) {
        const io::StrictIni ini(value("--config"));
        ini.loadChecked([&](const io::StrictIni& c) { loadMapMetricsParams(c, p); }, {"batch", "metrics"});
    }
    p.max_center_dist_m = number("--max-center-dist", p.max_center_dist_m, 1e-6, 100);
    if (!(p.max_center_dist_m > 0)) throw std::invalid_argument("simp-eval map: --max-center-dist must be > 0");
    if (has("--classes")) {
        p.classes.clear();  // the command line wins over [map_metrics] classes
        std::stringstream list(value("--classes"));
        for (std::string name; std::getline(list, name, ',');)
            if (!name.empty()) p.classes.push_back(name);
        if (p.classes.empty()) throw std::invalid_argument("simp-eval map: --classes needs at least one class name");
    }
    const world::World gt = world::loadWorld(gt_dir);
    const world::World map = world::loadWorld(map_dir);
    MapMetrics m;
    try {
        m = evaluateMap(gt.objects, map.objects, p);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("map '" + map_dir + "' vs ground truth '" + gt_dir + "': " + e.what());
    }
    out << "map evaluation: " << map_dir << " against " << gt_dir << " (centre gate " << fmt(p.max_center_dist_m, 2)
        << " m)\n\n"
        << mapMarkdownTable(m) << "\n";
    if (has("--png")) {
        writeFigure(value("--png"), drawMapEvaluation(gt, map, m), out);
    }
    if (has("--json")) {
        // Which objects the figures are about: ids and classes of the ground truth left unmatched and
        // of the map objects that match nothing, so that a user can look each one up.
        const auto listed = [](const world::ObjectMapData& data, const std::vector<std::size_t>& indices) {
            nlohmann::json list = nlohmann::json::array();
            for (std::size_t i : indices) {
                const auto& o = data.objects.at(i);
                list.push_back({{"id", o.id}, {"class", data.class_names.at(static_cast<std::size_t>(o.class_id))},
                                {"center_m", {o.box.center.x(), o.box.center.y(), o.box.center.z()}}});
            }
            return list;
        };
        nlohmann::json j = toJson(m);
        j["missed_ground_truth"] = listed(gt.objects, m.missed_gt);
        j["false_map_objects"] = listed(map.objects, m.false_pred);
        out << j.dump() << "\n";
    }
    return 0;
}

int EvalApp::runChanges(std::ostream& out) {
    const std::string truth_path = required("--truth"), report_path = required("--report");
    requireFile(truth_path, "true changes");
    requireFile(report_path, "change report");
    ChangeMatchParams p;
    p.max_center_dist_m = number("--max-center-dist", p.max_center_dist_m, 1e-6, 100);
    if (has("--classes")) {
        std::stringstream list(value("--classes"));
        for (std::string name; std::getline(list, name, ',');)
            if (!name.empty()) p.classes.push_back(name);
        if (p.classes.empty()) throw std::invalid_argument("simp-eval changes: --classes needs at least one class name");
    }
    if (has("--before-world") != has("--before-map"))
        throw std::invalid_argument("simp-eval changes: --before-world and --before-map go together");
    const auto truth_file = world::readChangesFile(truth_path);
    const auto report_file = world::readChangesFile(report_path);
    const auto& truth = truth_file.changes;
    const auto& report = report_file.changes;
    world::World w, m0;
    BeforeMaps before;
    std::string world_dir, map_dir;  // of `before`
    if (has("--before-world")) {
        world_dir = value("--before-world"), map_dir = value("--before-map");
        requireDir(world_dir, "before world");
        requireDir(map_dir, "before map");
        w = world::loadWorld(world_dir);
        m0 = world::loadWorld(map_dir);
        before.world = &w.objects;
        before.map = &m0.objects;
    } else if (!truth_file.before_world.empty() && !report_file.before_world.empty()) {
        // The files name the worlds their ids belong to (the simulator's W, simp-map --update's
        // M0): a report on a map built by simp-map speaks in that map's ids, not in W's.
        const std::string& wd = truth_file.before_world;
        const std::string& md = report_file.before_world;
        if (!fs::is_directory(wd) || !fs::is_directory(md)) {
            out << "warning: the truth's ids are those of '" << wd << "' and the report's of '" << md << "', and '"
                << (fs::is_directory(wd) ? md : wd)
                << "' is not a directory: removed and moved are scored by id as they stand (if the report's map "
                   "was built by simp-map, give --before-world W --before-map M0)\n";
        } else if (!fs::equivalent(wd, md)) {
            try {
                w = world::loadWorld(wd);
                m0 = world::loadWorld(md);
            } catch (const std::exception& e) {
                out << "warning: the change files' before_world cannot be read (" << e.what()
                    << "): removed and moved are scored by id as they stand\n";
                w = {}, m0 = {};
            }
            if (w.objects.objects.empty() || sameObjectIds(w.objects, m0.objects)) {
                w = {}, m0 = {};
            } else {
                world_dir = wd, map_dir = md;
                before.world = &w.objects;
                before.map = &m0.objects;
                out << "the report's ids are those of its map '" << md << "', the truth's those of the world '" << wd
                    << "' (each file's before_world): matched through their objects, as --before-world and "
                       "--before-map do\n";
            }
        }
    }
    if (has("--visited")) {
        if (!before.world)
            throw std::invalid_argument("simp-eval changes: --visited needs --before-world (its rooms.png), or change "
                                        "files whose before_world name a world and a built map");
        requireFile(value("--visited"), "visited trajectory");
        if (w.rooms.empty())
            throw std::invalid_argument("simp-eval changes: --visited: the before world '" + world_dir +
                                        "' has no rooms.png");
        p.rooms = &w.rooms;
        p.visited_rooms = visitedRooms(w.rooms, value("--visited"));
    }
    const ChangeScores s = scoreChanges(truth, report, p, before);
    out << "change evaluation: " << report_path << " against " << truth_path << " (added: centre gate "
        << fmt(p.max_center_dist_m, 2) << " m)\n\n"
        << changeMarkdownTable(s);
    if (before.world)
        out << "\nbefore map '" << map_dir << "': " << s.truth_not_in_map
            << " true removals of objects it never had (dropped), " << s.ignored_reports
            << " reports about its ghosts or objects it had missed (ignored)\n";
    if (p.rooms) out << "scored: changes in the " << p.visited_rooms.size() << " rooms the trajectory entered\n";
    if (has("--json")) out << toJson(s).dump() << "\n";
    return 0;
}

int EvalApp::runPlotMap(std::ostream& out) {
    const std::string dir = required("--world"), png = required("--png");
    requireDir(dir, "world");
    writeFigure(png, drawObjectMap(world::loadWorld(dir)), out);
    return 0;
}

int EvalApp::runBatch(std::ostream& out, std::ostream& err) {
    const std::string ini = required("--config"), out_dir = required("--out");
    BatchConfig cfg = loadBatchConfig(ini);
    if (has("--cores")) {
        cfg.cores = static_cast<int>(*args_.integer("cores", 1, 256));
    }
    fs::create_directories(out_dir);
    err << "batch configuration (" << ini << "):\n" << cfg.dump();
    // the maps first: a missing or malformed map fails in a second, not after hours of runs
    const auto maps = evaluateBatchMaps(cfg);
    const auto records = eval::runBatch(cfg, out_dir, err, &err == &std::cerr && ::isatty(STDERR_FILENO));
    const auto summary = summarize(cfg, records);
    const std::string md = batchMarkdown(cfg, summary) + batchMapsMarkdown(maps);
    const fs::path dir(out_dir);
    writeText(dir / "tables.md", md);
    writeText(dir / "runs.csv", runsCsv(records));
    writeText(dir / "summary.csv", summaryCsv(cfg, summary));
    if (!maps.empty()) writeText(dir / "maps.csv", batchMapsCsv(maps));
    writePng((dir / "success.png").string(), drawSuccessFigure(summary));
    writePng((dir / "error_over_time.png").string(),
             drawErrorOverTimeFigure(summary, loadRunErrors(cfg, summary, records, out_dir), cfg.metrics.max_trans_m));
    std::size_t failed = 0;
    for (const auto& r : records)
        if (r.status != "ok") {
            ++failed;
            err << "run " << r.sequence << "/" << r.method << "/seed" << r.seed << ": " << r.status << ": " << r.error
                << "\n";
        }
    out << md << "tables: " << (dir / "tables.md").string() << ", runs: " << (dir / "runs.csv").string()
        << ", summary: " << (dir / "summary.csv").string();
    if (!maps.empty()) out << ", maps: " << (dir / "maps.csv").string();
    out << "\nfigures: " << (dir / "success.png").string() << ", " << (dir / "error_over_time.png").string() << "\n";
    if (failed) out << failed << " of " << records.size() << " runs failed (counted as unsuccessful)\n";
    return 0;
}

}  // namespace simp::eval
