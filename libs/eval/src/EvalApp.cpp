#include <simp/eval/EvalApp.h>
#include <simp/io/CommandSet.h>

#include <sstream>
#include <stdexcept>

namespace simp::eval {

io::CommandSet EvalApp::commandSet() {
    io::CommandSet set("simp-eval", "simp-eval: the paper's localization and map metrics, batch experiments and plots.");
    set.add("traj", "success, convergence time, ATE after convergence (defaults: 0.3 m, pi/4 rad, 1.5 s, 0.95)")
        .required("gt", "Q/groundtruth.tum", "ground truth (TUM)")
        .required("est", "O/estimate.tum", "estimate (TUM)")
        .flag("json", "print one JSON object on the last line of standard output")
        .option("png", "F", "also draw the trajectories")
        .option("world", "W", "the floor plan under the --png figure")
        .option("config", "INI", "[metrics] max_trans_m, max_rot_rad, max_outside_s, convergence_fraction\n"
                                 "(command-line options override)")
        .option("max-trans", "M", "convergence gate, translation (m)")
        .option("max-rot", "RAD", "convergence gate, rotation (rad)")
        .option("max-outside", "S", "accumulated time outside the gates that counts as diverged (s)")
        .option("fraction", "F", "converged within this fraction of the duration");
    set.add("map", "per-class footprint IoU, precision, recall of the object map M against W (gate 1.0 m)")
        .required("gt", "W", "ground-truth world directory")
        .required("map", "M", "the built map (a world directory)")
        .flag("json", "print one JSON object on the last line of standard output")
        .option("png", "F", "also draw the evaluation")
        .option("config", "INI", "[map_metrics] max_center_dist_m, classes (command-line options override)")
        .option("max-center-dist", "M", "matching gate (m)")
        .option("classes", "a,b,...", "evaluate only these classes");
    set.add("changes", "precision and recall per kind of change: removed / moved matched by id_before, added by class\n"
                       "and centre distance (gate 1.0 m)")
        .required("truth", "Q/changes.json", "the true changes (simp-sim sequence)")
        .required("report", "M/changes.json", "the detected changes (simp-map --update)")
        .flag("json", "print one JSON object on the last line of standard output")
        .option("max-center-dist", "M", "matching gate (m)")
        .option("classes", "a,b,...", "evaluate only these classes")
        .option("before-world", "W", "with --before-map: the report's ids are those of a built map M0, matched to\n"
                                     "W's objects by class and centre distance (default: the files' before_world)")
        .option("before-map", "M0", "the built map the report's ids refer to (with --before-world)")
        .option("visited", "TUM", "Q/groundtruth.tum (with --before-world): only changes in the rooms of W the\n"
                                  "trajectory entered");
    set.add("plot-map", "the object map of W over its floor plan, boxes coloured by class")
        .required("world", "W", "world directory")
        .required("png", "F", "the figure to write");
    set.add("batch", "runs simp-localize for sequences x localization configs x methods x seeds (resumable),\n"
                     "evaluates the built maps of [batch] maps (Table I); writes DIR/tables.md, DIR/runs.csv,\n"
                     "DIR/summary.csv, DIR/maps.csv, DIR/success.png, DIR/error_over_time.png")
        .required("config", "config_ini/batch.ini", "the experiment")
        .required("out", "DIR", "output directory")
        .option("cores", "N", "parallel runs, in [1, 256]");
    set.notes("--json prints one JSON object on the last line of standard output.\nDefinitions: doc/evaluation.md.");
    return set;
}

std::string EvalApp::usage() { return commandSet().help(); }

void EvalApp::initialize(int argc, const char* const* argv) {
    command_.clear();
    help_ = false;
    io::CommandSet set = commandSet();
    std::ostringstream help;
    const io::CommandLine* c = set.parse(argc, argv, help);
    help_ = c == nullptr;
    if (help_) return;
    command_ = argv[1];
    args_ = *c;
}

const std::string& EvalApp::required(const std::string& key) const { return args_.value(key.substr(2)); }

bool EvalApp::has(const std::string& key) const { return args_.has(key.substr(2)); }

const std::string& EvalApp::value(const std::string& key) const { return args_.value(key.substr(2)); }

double EvalApp::number(const std::string& key, double fallback, double lo, double hi) const {
    return args_.number(key.substr(2), lo, hi).value_or(fallback);
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
