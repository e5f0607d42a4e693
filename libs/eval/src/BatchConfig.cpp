#include <mrpt/config/CConfigFile.h>
#include <simp/eval/BatchConfig.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace simp::eval {
namespace {

std::vector<std::string> splitList(const std::string& s) {
    std::string t = s;
    std::replace(t.begin(), t.end(), ',', ' ');
    std::istringstream in(t);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

const std::vector<std::string> kMethods{"simp", "edt", "d", "o"};

}  // namespace

std::string methodLabel(const std::string& method) {
    if (method == "simp") return "Ours";
    if (method == "edt") return "EDT-MCL";
    if (method == "d") return "D-MCL";
    if (method == "o") return "O-MCL";
    return method;
}

BatchConfig loadBatchConfig(const std::string& ini_path) {
    if (!std::filesystem::is_regular_file(ini_path))
        throw std::runtime_error("batch config '" + ini_path + "': file not found");
    mrpt::config::CConfigFile ini(ini_path);
    const auto fail = [&](const std::string& key, const std::string& why) {
        throw std::runtime_error("batch config '" + ini_path + "', key '" + key + "': " + why);
    };
    BatchConfig c;
    const std::string S = "batch";
    c.world = ini.read_string(S, "world", "");
    if (c.world.empty()) fail("[batch] world", "required (the localization map's world directory)");
    c.map_name = ini.read_string(S, "map_name", c.map_name);
    const auto dirs = splitList(ini.read_string(S, "sequences", ""));
    if (dirs.empty()) fail("[batch] sequences", "required (list of sequence directories)");
    const auto names = splitList(ini.read_string(S, "sequence_names", ""));
    if (!names.empty() && names.size() != dirs.size())
        fail("[batch] sequence_names", std::to_string(names.size()) + " names for " + std::to_string(dirs.size()) +
                                           " sequences");
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        std::string name = names.empty() ? std::filesystem::path(dirs[i]).lexically_normal().filename().string()
                                         : names[i];
        if (name.empty()) name = "S" + std::to_string(i + 1);
        for (const auto& s : c.sequences)
            if (s.name == name) fail("[batch] sequences", "two sequences are named '" + name + "' (set sequence_names)");
        c.sequences.push_back({name, dirs[i]});
    }
    const auto methods = splitList(ini.read_string(S, "methods", ""));
    if (!methods.empty()) c.methods = methods;
    for (const auto& m : c.methods)
        if (std::find(kMethods.begin(), kMethods.end(), m) == kMethods.end())
            fail("[batch] methods", "unknown method '" + m + "' (known: simp edt d o)");
    c.repetitions = ini.read_int(S, "repetitions", c.repetitions);
    if (c.repetitions < 1) fail("[batch] repetitions", "must be >= 1");
    c.first_seed = ini.read_int(S, "first_seed", c.first_seed);
    c.cores = ini.read_int(S, "cores", c.cores);
    if (c.cores < 1) fail("[batch] cores", "must be >= 1");
    c.localize_bin = ini.read_string(S, "localize_bin", "");
    c.localize_config = ini.read_string(S, "localize_config", "");
    c.particles = ini.read_int(S, "particles", 0);
    if (c.particles < 0) fail("[batch] particles", "must be >= 0");
    c.extra_args = splitList(ini.read_string(S, "extra_args", ""));

    const std::string M = "metrics";
    c.metrics.max_trans_m = ini.read_double(M, "max_trans_m", c.metrics.max_trans_m);
    c.metrics.max_rot_rad = ini.read_double(M, "max_rot_rad", c.metrics.max_rot_rad);
    c.metrics.max_outside_s = ini.read_double(M, "max_outside_s", c.metrics.max_outside_s);
    c.metrics.convergence_fraction = ini.read_double(M, "convergence_fraction", c.metrics.convergence_fraction);
    if (!(c.metrics.max_trans_m > 0)) fail("[metrics] max_trans_m", "must be > 0");
    if (!(c.metrics.max_rot_rad > 0)) fail("[metrics] max_rot_rad", "must be > 0");
    if (!(c.metrics.max_outside_s >= 0)) fail("[metrics] max_outside_s", "must be >= 0");
    if (!(c.metrics.convergence_fraction > 0 && c.metrics.convergence_fraction <= 1))
        fail("[metrics] convergence_fraction", "must be in (0, 1]");
    return c;
}

std::string BatchConfig::dump() const {
    std::ostringstream s;
    s << "world = " << world << "\nmap_name = " << map_name << "\nsequences =";
    for (const auto& q : sequences) s << " " << q.name << ":" << q.dir;
    s << "\nmethods =";
    for (const auto& m : methods) s << " " << m;
    s << "\nrepetitions = " << repetitions << "\nfirst_seed = " << first_seed << "\ncores = " << cores
      << "\nlocalize_bin = " << localize_bin << "\nlocalize_config = " << localize_config
      << "\nparticles = " << particles << "\nextra_args =";
    for (const auto& a : extra_args) s << " " << a;
    s << "\n[metrics] max_trans_m = " << metrics.max_trans_m << ", max_rot_rad = " << metrics.max_rot_rad
      << ", max_outside_s = " << metrics.max_outside_s << ", convergence_fraction = " << metrics.convergence_fraction
      << "\n";
    return s.str();
}

}  // namespace simp::eval
