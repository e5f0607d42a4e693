#pragma once
/// \file ObjectMapData.h
/// The content of an object map file: class list, per-class noise models, objects.

#include <simp/world/MapObject.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::world {

struct ObjectMapData {
    std::vector<std::string> class_names;             ///< class id -> name
    std::vector<std::optional<NoiseModel>> class_noise;  ///< per class id; empty = not modelled
    std::vector<MapObject> objects;

    /// Class id of `name`, or -1.
    int classId(const std::string& name) const;
    /// Noise of object o: its own, else its class's; nullopt when neither exists.
    std::optional<NoiseModel> noiseOf(const MapObject& o) const;
};

/// Reads / writes the project's object map file (JSON, documented in doc/formats.md).
/// Errors name the file, the entry (object index / class) and the key.
ObjectMapData loadObjectMap(const std::string& path);
void saveObjectMap(const ObjectMapData& data, const std::string& path);

/// Default heights (m) of the paper's classes, used where a source has footprints only.
double defaultClassHeight(const std::string& class_name);

}  // namespace simp::world
