#pragma once
/// \file Subprocess.h
/// Running another program of the suite (simp-localize) as a child process.

#include <string>
#include <vector>

namespace simp::eval {

/// Runs argv[0] (a path, or a name looked up in PATH) with the arguments argv[1..], standard
/// output and error appended to `log_path`, and waits for it.
/// \return the exit status (0..255), or 128 + signal number when the child was killed.
/// \throw std::runtime_error naming the program when it cannot be started or the log opened.
int runProcess(const std::vector<std::string>& argv, const std::string& log_path);

/// Directory of the running executable (/proc/self/exe), empty when unknown.
std::string executableDir();

}  // namespace simp::eval
