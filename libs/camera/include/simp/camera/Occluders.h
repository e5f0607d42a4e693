#pragma once
/// \file Occluders.h
/// Which objects hide what lies behind them, the same rule for simulator, mapper, localization and
/// label generator (doc/architecture.md "Camera and visibility"):
/// - a door object stands in an open doorway: the floor plan leaves the gap free and a closed door
///   is drawn into the floor plan as wall (sim::closeDoor), so the door box is seen (it is a
///   detectable object) but hides nothing;
/// - a table is a top on legs: it hides with its top (kOpenBelowTop_m thick), and what stands under
///   or behind it below the top is seen between its legs (drawers under a table; the cameras are
///   mounted lower than a table's top);
/// - every other object is a solid box.

#include <string>
#include <vector>

namespace simp::camera {

/// The class name of door objects.
inline constexpr const char* kDoorClass = "door";
/// The class name of the objects open below their top.
inline constexpr const char* kTableClass = "table";

/// How a box occludes in ZBufferParams::occludes (one char per box).
enum OcclusionKind : char {
    kSeeThrough = 0,  ///< seen, hides nothing (doors)
    kSolid = 1,       ///< the whole box hides
    kOpenBelow = 2,   ///< only the top kOpenBelowTop_m of the box hides (tables)
};

/// Thickness of the part of an open-below box that hides (m): a table's top and its apron.
inline constexpr double kOpenBelowTop_m = 0.1;

/// The OcclusionKind of objects of `class_name`.
OcclusionKind occlusionOf(const std::string& class_name);

/// True when objects of `class_name` hide anything (false for doors).
bool occludes(const std::string& class_name);

/// occlusionOf() per class id, for the class list of a world (ids outside the list are solid).
std::vector<char> occludingClasses(const std::vector<std::string>& class_names);

/// The OcclusionKind of class id `class_id` in a list made by occludingClasses(); an id outside
/// the list (negative or too large) is solid.
char occlusionOfClassId(const std::vector<char>& class_kinds, int class_id);

}  // namespace simp::camera
