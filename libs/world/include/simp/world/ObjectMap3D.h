#pragma once
/// \file ObjectMap3D.h
/// The objects of an object map as MRPT 3D primitives: what RawLogViewer, SceneViewer3D and
/// the apps' .3Dscene files show of a map.

#include <mrpt/opengl/CSetOfObjects.h>
#include <simp/world/ObjectMapData.h>

namespace simp::world {

/// Appends, per object, one wireframe mrpt::opengl::CBox (the box in the world frame, in its
/// class colour) and one mrpt::opengl::CText label "<class> #<id>"
/// above it (simp::obs::appendLabelledBox). So `out` gains 2 * map.objects.size() primitives.
void appendObjectBoxes(const ObjectMapData& map, mrpt::opengl::CSetOfObjects& out);

}  // namespace simp::world
