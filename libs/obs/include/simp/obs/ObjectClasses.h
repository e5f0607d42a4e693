#pragma once
/// \file ObjectClasses.h
/// The detector's label set: class id -> class name.

#include <string>
#include <vector>

namespace simp::obs {

/// The 14 classes of the paper's detector, in Omni3D / Cube R-CNN index order
/// (`category_meta.json` of the authors' release).
const std::vector<std::string>& defaultClassNames();

/// The ten classes of the paper's Table I, the ones the authors map and evaluate (their detector's
/// classes but door, box, chair and person). Maps are scored on these (the project also maps doors,
/// for localization: config_ini/mapping.ini).
const std::vector<std::string>& tableIClassNames();

/// Index of `name` in `names`, or -1 when absent.
int classIndexOf(const std::vector<std::string>& names, const std::string& name);

}  // namespace simp::obs
