#pragma once
/// \file BadInputCase.h
/// One row of tests/bad_input/cases.tsv and how it runs (doc/bad-input.md describes the columns).

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace simp_bad_input {

struct Case {
    int line = 0;              ///< line in cases.tsv (for messages)
    std::string app;           ///< binary in build/bin
    int exit_code = 1;         ///< expected exit code (non-zero)
    std::string fragment;      ///< expected in stdout + stderr
    std::string args;          ///< command-line arguments ($T, $W, ... substituted)
    std::string files;         ///< files to create in $T: "path=spec || path=spec ..."
};

/// $NAME -> value ($T is added per case).
using Variables = std::map<std::string, std::string>;

struct RunResult {
    bool exited = false;       ///< false: killed by a signal or the timeout
    int code = -1;             ///< exit code, or the signal number
    bool timed_out = false;
    double seconds = 0;
};

struct Outcome {
    bool ok = false;
    std::string problem;       ///< why not ok
    std::string output;        ///< stdout + stderr
    double seconds = 0;        ///< wall time of the process
};

/// Rows of the table ('#' lines and blank lines skipped). \throw std::runtime_error naming the line.
std::vector<Case> readCases(const std::string& path);
/// `text` with every $NAME of `vars` replaced (longest name first).
std::string substitute(const std::string& text, const Variables& vars);
/// Splits on blanks; "..." groups (with \" inside), "" is an empty argument.
std::vector<std::string> splitArgs(const std::string& text);
/// Creates the files of a case in `dir` (see doc/bad-input.md for the specs).
void createFiles(const std::string& files, const std::filesystem::path& dir, const Variables& vars);
/// Runs argv[0] with stdout and stderr into `log`, in the folder of `log`, killed after `timeout_s`.
RunResult runProcess(const std::vector<std::string>& argv, const std::filesystem::path& log, double timeout_s);
/// Creates the case's folder and files, runs it, judges it.
Outcome runCase(const Case& c, const std::filesystem::path& cases_root, Variables vars);

}  // namespace simp_bad_input
