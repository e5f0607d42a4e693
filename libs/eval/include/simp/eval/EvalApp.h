#pragma once
/// \file EvalApp.h
/// The logic of the simp-eval program (apps/simp-eval is a thin main around it), so the
/// sub-commands can be run and tested in-process. Command lines: doc/evaluation.md.
///
///   simp-eval traj --gt GT.tum --est EST.tum [--json] [--png F [--world W]] [--config INI]
///   simp-eval map --gt W --map M [--json] [--png F] [--config INI] [--max-center-dist M]
///   simp-eval changes --truth Q/changes.json --report M/changes.json [--json] [--before-world W --before-map M0]
///   simp-eval plot-map --world W --png F
///   simp-eval batch --config config_ini/batch.ini --out DIR [--cores N]

#include <simp/io/CommandSet.h>

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace simp::eval {

class EvalApp {
public:
    /// Parses the command line. \throw std::invalid_argument with a usage hint on an unknown
    /// sub-command or option, or a missing value.
    void initialize(int argc, const char* const* argv);

    /// Runs the sub-command; results on `out`, progress on `err`. Returns the exit code.
    /// \throw std::exception on bad input (missing or malformed file, ...).
    int run(std::ostream& out, std::ostream& err);

    /// Full usage text.
    static std::string usage();
    /// The declared sub-commands and their options (the --help text and the checks derive from them).
    static io::CommandSet commandSet();

private:
    std::string command_;
    io::CommandLine args_{"simp-eval"};  ///< the parsed sub-command
    bool help_ = false;

    /// @name The parsed options by "--key"
    /// @{
    bool has(const std::string& key) const;
    const std::string& value(const std::string& key) const;
    const std::string& required(const std::string& key) const;  ///< a required option (checked by the parser)
    /// The option's value as a finite number in [lo, hi] (io::parseNumber), or `fallback` when absent.
    double number(const std::string& key, double fallback, double lo, double hi) const;
    /// @}

    int runTraj(std::ostream& out);
    int runMap(std::ostream& out);
    int runPlotMap(std::ostream& out);
    int runChanges(std::ostream& out);
    int runBatch(std::ostream& out, std::ostream& err);
};

}  // namespace simp::eval
