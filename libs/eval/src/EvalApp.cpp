#include <simp/eval/EvalApp.h>
#include <simp/io/StrictNumber.h>

#include <cmath>
#include <set>
#include <stdexcept>

namespace simp::eval {
namespace {

/// Options of each sub-command; true = takes a value.
const std::map<std::string, std::map<std::string, bool>>& knownOptions() {
    static const std::map<std::string, std::map<std::string, bool>> k{
        {"traj",
         {{"--gt", true}, {"--est", true}, {"--json", false}, {"--png", true}, {"--world", true}, {"--config", true},
          {"--max-trans", true}, {"--max-rot", true}, {"--max-outside", true}, {"--fraction", true}}},
        {"map",
         {{"--gt", true}, {"--map", true}, {"--json", false}, {"--png", true}, {"--config", true},
          {"--max-center-dist", true}, {"--classes", true}}},
        {"plot-map", {{"--world", true}, {"--png", true}}},
        {"changes",
         {{"--truth", true}, {"--report", true}, {"--json", false}, {"--max-center-dist", true}, {"--classes", true},
          {"--before-world", true}, {"--before-map", true}, {"--visited", true}}},
        {"batch", {{"--config", true}, {"--out", true}, {"--cores", true}}},
    };
    return k;
}

}  // namespace

std::string EvalApp::usage() {
    return "simp-eval: the paper's localization and map metrics, batch experiments and plots.\n"
           "\n"
           "Usage:\n"
           "  simp-eval traj --gt Q/groundtruth.tum --est O/estimate.tum [--json] [--png F [--world W]]\n"
           "                 [--config INI] [--max-trans M] [--max-rot RAD] [--max-outside S] [--fraction F]\n"
           "      success, convergence time, ATE after convergence (defaults: 0.3 m, pi/4 rad, 1.5 s, 0.95)\n"
           "  simp-eval map --gt W --map M [--json] [--png F] [--config INI] [--max-center-dist M]\n"
           "                [--classes a,b,...]   (evaluate only these classes)\n"
           "      per-class footprint IoU, precision, recall of the object map M against W (gate 1.0 m)\n"
           "  simp-eval changes --truth Q/changes.json --report M/changes.json [--json] [--max-center-dist M]\n"
           "                    [--classes a,b,...] [--before-world W --before-map M0] [--visited TUM]\n"
           "      precision and recall per kind of change: removed / moved matched by id_before, added by class\n"
           "      and centre distance (gate 1.0 m); --before-world/--before-map: the report's ids are those of a\n"
           "      built map M0, matched to W's objects by class and centre distance; --visited Q/groundtruth.tum\n"
           "      (with --before-world): only changes in the rooms of W the trajectory entered\n"
           "  simp-eval plot-map --world W --png F\n"
           "      the object map of W over its floor plan, boxes coloured by class\n"
           "  simp-eval batch --config config_ini/batch.ini --out DIR [--cores N]\n"
           "      runs simp-localize for sequences x localization configs x methods x seeds (resumable),\n"
           "      evaluates the built maps of [batch] maps (Table I); writes DIR/tables.md, DIR/runs.csv,\n"
           "      DIR/summary.csv, DIR/maps.csv, DIR/success.png, DIR/error_over_time.png\n"
           "\n"
           "--json prints one JSON object on the last line of standard output.\n"
           "--config INI: [metrics] max_trans_m, max_rot_rad, max_outside_s, convergence_fraction;\n"
           "              [map_metrics] max_center_dist_m, classes (command-line options override).\n"
           "Definitions: doc/evaluation.md.\n";
}

void EvalApp::initialize(int argc, const char* const* argv) {
    command_.clear();
    options_.clear();
    help_ = false;
    if (argc < 2) throw std::invalid_argument("missing sub-command (traj, map, changes, plot-map, batch); see --help");
    command_ = argv[1];
    if (command_ == "--help" || command_ == "-h" || command_ == "help") {
        help_ = true;
        return;
    }
    const auto known = knownOptions().find(command_);
    if (known == knownOptions().end())
        throw std::invalid_argument("unknown sub-command '" + command_ + "' (traj, map, changes, plot-map, batch); see --help");
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            help_ = true;
            continue;
        }
        const auto opt = known->second.find(a);
        if (opt == known->second.end())
            throw std::invalid_argument("simp-eval " + command_ + ": unknown option '" + a + "'; see --help");
        if (!opt->second) {
            options_[a] = "";
            continue;
        }
        if (i + 1 >= argc) throw std::invalid_argument("simp-eval " + command_ + ": option " + a + " needs a value");
        options_[a] = argv[++i];
    }
}

const std::string& EvalApp::required(const std::string& key) const {
    const auto it = options_.find(key);
    if (it == options_.end() || it->second.empty())
        throw std::invalid_argument("simp-eval " + command_ + ": missing required option " + key + "; see --help");
    return it->second;
}

double EvalApp::number(const std::string& key, double fallback, double lo, double hi) const {
    const auto it = options_.find(key);
    if (it == options_.end()) return fallback;
    return io::parseNumber(it->second, "simp-eval " + command_ + ": option " + key, lo, hi);
}

int EvalApp::run(std::ostream& out, std::ostream& err) {
    if (help_) {
        out << usage();
        return 0;
    }
    if (command_ == "traj") return runTraj(out);
    if (command_ == "map") return runMap(out);
    if (command_ == "plot-map") return runPlotMap(out);
    if (command_ == "changes") return runChanges(out);
    if (command_ == "batch") return runBatch(out, err);
    throw std::logic_error("simp-eval: initialize() was not called");
}

}  // namespace simp::eval
