#pragma once
/// \file ObjectMapData.h
/// The content of an object map file: class list, per-class noise models, objects.

#include <simp/world/MapObject.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::world {

/// Optional description of a room of the room raster (rooms.png); only names, for
/// humans and for the authors' floor.config.
struct RoomInfo {
    int id = 0;                 ///< value in rooms.png (>= 1; 0 = no room)
    std::string name;           ///< free text (the authors use "0", "1", ...)
    std::string category;       ///< e.g. "office", "kitchen"; empty = unknown
};

struct ObjectMapData {
    std::vector<std::string> class_names;             ///< class id -> name
    std::vector<std::optional<model::NoiseModel>> class_noise;  ///< per class id; empty = not modelled
    std::vector<MapObject> objects;
    std::vector<RoomInfo> rooms;                      ///< optional room names (may be empty)
    std::vector<std::string> room_categories;         ///< optional ordered category list (may be empty)

    /// Class id of `name`, or -1.
    int classId(const std::string& name) const;
    /// Noise of object o: its own, else its class's; nullopt when neither exists.
    std::optional<model::NoiseModel> noiseOf(const MapObject& o) const;
};

/// Reads / writes the project's object map file (JSON, documented in doc/formats.md).
/// Errors name the file, the entry (object index / class) and the key.
/// \throw std::runtime_error on a missing/unreadable file, malformed JSON, a missing key,
///        a wrong type or range, an unknown class name, a duplicate id or an unknown version.
ObjectMapData loadObjectMap(const std::string& path);
/// Writes `data` (validated first, same checks as loadObjectMap); doubles are written with
/// full round-trip precision, so load(save(x)) == x. Creates missing parent folders.
void saveObjectMap(const ObjectMapData& data, const std::string& path);

/// Checks the content of an object map (class ids in range, sizes > 0, rotations, noise,
/// unique ids). `where` prefixes the messages (usually the file name).
/// \throw std::runtime_error naming where, the object index and the key.
void validateObjectMap(const ObjectMapData& data, const std::string& where);

/// Default heights (m) of the paper's 14 classes (simp::obs::defaultClassNames()), used
/// where a source has footprints only (doc/formats.md lists them).
/// \throw std::invalid_argument for any other name.
double defaultClassHeight(const std::string& class_name);

}  // namespace simp::world
