#include <simp/io/StrictIni.h>
#include <simp/eval/BatchConfig.h>

#include <algorithm>
#include <cmath>
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

const std::vector<std::string> kMethods{"simp", "edt", "d", "o", "lidar", "simp+lidar"};

}  // namespace

std::string methodLabel(const std::string& method) {
    if (method == "simp") return "Ours";
    if (method == "edt") return "EDT-MCL";
    if (method == "d") return "D-MCL";
    if (method == "o") return "O-MCL";
    if (method == "lidar") return "LiDAR-MCL";
    if (method == "simp+lidar") return "Ours+LiDAR";
    return method;
}

namespace {
BatchConfig loadBatchConfigStrict(const std::string& ini_path) {
    const io::StrictIni ini(ini_path);  // exists, is a file, is an .ini
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
            fail("[batch] methods", "unknown method '" + m + "' (known: simp edt d o lidar simp+lidar)");
    c.repetitions = static_cast<int>(ini.readInteger(S, "repetitions", c.repetitions, 1, 1000));
    c.first_seed = static_cast<int>(ini.readInteger(S, "first_seed", c.first_seed, 0, 2147483647));
    c.cores = static_cast<int>(ini.readInteger(S, "cores", c.cores, 1, 256));
    c.localize_bin = ini.read_string(S, "localize_bin", "");
    c.localize_config = ini.read_string(S, "localize_config", "");
    c.particles = static_cast<int>(ini.readInteger(S, "particles", 0, 0, 500000));
    c.extra_args = splitList(ini.read_string(S, "extra_args", ""));

    const std::string M = "metrics";
    c.metrics.max_trans_m = ini.readNumber(M, "max_trans_m", c.metrics.max_trans_m, 1e-6, 1e3);
    c.metrics.max_rot_rad = ini.readNumber(M, "max_rot_rad", c.metrics.max_rot_rad, 1e-6, 2 * M_PI);
    c.metrics.max_outside_s = ini.readNumber(M, "max_outside_s", c.metrics.max_outside_s, 0, 1e6);
    c.metrics.convergence_fraction = ini.readNumber(M, "convergence_fraction", c.metrics.convergence_fraction, 1e-6, 1);
    if (!(c.metrics.max_trans_m > 0)) fail("[metrics] max_trans_m", "must be > 0");
    if (!(c.metrics.max_rot_rad > 0)) fail("[metrics] max_rot_rad", "must be > 0");
    if (!(c.metrics.max_outside_s >= 0)) fail("[metrics] max_outside_s", "must be >= 0");
    if (!(c.metrics.convergence_fraction > 0 && c.metrics.convergence_fraction <= 1))
        fail("[metrics] convergence_fraction", "must be in (0, 1]");
    ini.checkUnknown({"map_metrics"});
    return c;
}
}  // namespace

BatchConfig loadBatchConfig(const std::string& ini_path) {
    try {
        return loadBatchConfigStrict(ini_path);
    } catch (const std::invalid_argument& e) {  // io::StrictIni's errors: this function throws runtime_error
        throw std::runtime_error(e.what());
    }
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
