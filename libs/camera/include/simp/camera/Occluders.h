#pragma once
/// \file Occluders.h
/// Which objects hide what lies behind them, the same rule for simulator, mapper and label
/// generator. A door object stands in an open doorway: the floor plan leaves the gap free and a
/// closed door is drawn into the floor plan as wall (sim::closeDoor), so the door box is seen
/// (it is a detectable object) but hides nothing; every other object is solid.

#include <string>
#include <vector>

namespace simp::camera {

/// The class name of door objects.
inline constexpr const char* kDoorClass = "door";

/// True when objects of `class_name` hide what lies behind them (false for doors).
bool occludes(const std::string& class_name);

/// occludes() per class id, for the class list of a world (ids outside the list occlude).
std::vector<char> occludingClasses(const std::vector<std::string>& class_names);

}  // namespace simp::camera
