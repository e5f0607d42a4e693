#pragma once
/// \file IniKeys.h
/// Unknown-key check for .ini sections: MRPT's config readers ignore keys they do not ask for,
/// so a misspelt key would silently keep its default.

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace simp::io {

/// Throws std::invalid_argument naming `file`, the section and the key when `section`
/// holds a key that is not in `known` (nothing when the section is absent).
void checkKnownKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                    const std::vector<std::string>& known, const std::string& file);

}  // namespace simp::io
