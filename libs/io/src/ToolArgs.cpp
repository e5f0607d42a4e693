/// \file ToolArgs.cpp
#include <simp/io/ToolArgs.h>

#include <algorithm>
#include <stdexcept>

namespace simp::io {

ToolArgs parseToolArgs(int argc, const char* const* argv, const std::vector<std::string>& required,
                       const std::vector<std::string>& optional) {
    ToolArgs a;
    const auto known = [&](const std::string& k) {
        return std::find(required.begin(), required.end(), k) != required.end() ||
               std::find(optional.begin(), optional.end(), k) != optional.end();
    };
    for (int i = 1; i < argc; ++i) {
        const std::string s = argv[i];
        if (s == "--help" || s == "-h") {
            a.help = true;
            return a;
        }
        if (s.rfind("--", 0) != 0 || !known(s.substr(2))) throw std::invalid_argument("unknown option '" + s + "' (see --help)");
        if (i + 1 >= argc) throw std::invalid_argument("option " + s + " needs a value (see --help)");
        a.values[s.substr(2)] = argv[++i];
    }
    for (const std::string& k : required)
        if (!a.has(k)) throw std::invalid_argument("missing required option --" + k + " (see --help)");
    return a;
}

}  // namespace simp::io
