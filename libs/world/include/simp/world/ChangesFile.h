#pragma once
/// \file ChangesFile.h
/// The change file `changes.json` (doc/formats.md "changes.json"): what changed between a
/// "before" and an "after" world. The simulator writes the truth (Q/changes.json), simp-map
/// --update writes what it detected (M/changes.json, with a confidence per entry) and simp-eval
/// changes scores one against the other, all through these two functions.

#include <simp/geometry/Box3D.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace simp::world {

/// One entry of `changes`.
struct ChangeRecord {
    std::string kind;                          ///< "removed", "moved", "added" or "door_closed"
    std::optional<std::int64_t> id_before;     ///< id in the "before" world; none for added
    std::optional<std::int64_t> id_after;      ///< id in the "after" world; none for removed
    std::string class_name;                    ///< class name
    std::optional<geometry::Box3D> before;     ///< box in the "before" world (upright); none for added
    std::optional<geometry::Box3D> after;      ///< box in the "after" world (upright); none for removed
    std::optional<double> confidence;          ///< detected changes only, in [0, 1]
};

/// A change file's content: its entries and the world directory their `before` ids and boxes
/// belong to (`before_world`; empty when the file does not say).
struct ChangesFileContent {
    std::vector<ChangeRecord> changes;
    /// As read: resolved against the file's folder (the file stores it relative to itself).
    std::string before_world;
};

/// Writes `changes` as the change file `path` (format "simp-changes", version 1), in the given order.
/// `before_world` (optional): the world directory whose objects the `before` ids are (the
/// simulator's W, simp-map --update's M0), stored relative to the file's folder so that the
/// pair can move together. \throw std::runtime_error naming the file when it cannot be written.
void saveChangesFile(const std::vector<ChangeRecord>& changes, const std::string& path,
                     const std::string& before_world = {});

/// Reads a change file. Boxes are upright (centre, size, yaw_rad).
/// \throw std::runtime_error naming the file, the entry and the key ("F: changes[3].kind: ...")
///        on a missing file, invalid JSON, a wrong format/version or a malformed entry.
std::vector<ChangeRecord> loadChangesFile(const std::string& path);

/// loadChangesFile with `before_world` (a string when present, else the same errors).
ChangesFileContent readChangesFile(const std::string& path);

}  // namespace simp::world
