#include <simp/io/IniKeys.h>

#include <algorithm>
#include <stdexcept>

namespace simp::io {

void checkKnownKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                    const std::vector<std::string>& known, const std::string& file) {
    if (!cfg.sectionExists(section)) return;
    std::vector<std::string> keys;
    cfg.getAllKeys(section, keys);
    for (const auto& k : keys) {
        if (std::find(known.begin(), known.end(), k) != known.end()) continue;
        std::string list;
        for (const auto& x : known) list += (list.empty() ? "" : ", ") + x;
        throw std::invalid_argument(file + ": unknown key '" + k + "' in section [" + section + "] (known keys: " + list + ")");
    }
}

}  // namespace simp::io
