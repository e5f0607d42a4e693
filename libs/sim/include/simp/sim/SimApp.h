#pragma once
/// \file SimApp.h
/// The logic of the `simp-sim` program (apps/simp-sim is a try/catch around it):
///   simp-sim world --builtin office --seed S --out W [--size-m2 A | --rooms N] [--config INI]
///   simp-sim sequence --world W --seed S --out Q [--config INI] [--duration SEC] [--changes F] [--coverage] [--lidar]
///                     [--kidnap-at SEC]

#include <simp/io/CommandSet.h>

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace simp::sim {

class SimApp {
   public:
    /// Parses the command line. Returns false when only help was asked for (printed to `out`).
    /// \throw std::invalid_argument naming the option for a bad or missing one.
    bool initialize(const std::vector<std::string>& args, std::ostream& out);
    /// Runs the parsed command. \throw std::runtime_error on bad input files / failures.
    void run(std::ostream& out);

    static std::string usage();
    static io::CommandSet commandSet();  ///< the declared commands and options

    std::string command;               ///< "world" or "sequence"
    std::string builtin = "office";
    std::string out_dir, world_dir, config_path;
    std::uint64_t seed = 0;
    bool seed_given = false;
    std::optional<double> size_m2, duration_s, changes;
    std::optional<double> kidnap_at_s;  ///< --kidnap-at: teleport time after the start (s)
    bool coverage = false;  ///< --coverage
    bool lidar = false;     ///< --lidar: [lidar] enabled = true
    std::optional<int> rooms;
};

}  // namespace simp::sim
