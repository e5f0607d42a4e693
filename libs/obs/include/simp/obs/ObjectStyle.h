#pragma once
/// \file ObjectStyle.h
/// How an object looks in every picture of the project: one colour per class, shared by the 2D
/// figures (simp::eval::classColor, BGR), the 3D views (the observation in RawLogViewer, the object
/// map's getVisualizationInto) and the .3Dscene files (simp::eval::buildScene); one 3D primitive
/// for a labelled box.

#include <mrpt/opengl/CSetOfObjects.h>
#include <simp/geometry/Box3D.h>

#include <array>
#include <cstdint>
#include <string>

namespace simp::obs {

/// RGB (0..255) of class id `class_id`: a fixed 14-colour palette (one per class of the paper's
/// detector, Tableau 10 then four light Tableau 20 colours), repeating beyond; negative ids map
/// like their absolute value.
std::array<std::uint8_t, 3> classColorRgb(int class_id);

/// Appends to `out` a wireframe mrpt::opengl::CBox of `box` (in `out`'s frame) in the colour of
/// `class_id` and an mrpt::opengl::CText `label` 0.1 m above the box's top, same colour.
void appendLabelledBox(const geometry::Box3D& box, int class_id, const std::string& label,
                       mrpt::opengl::CSetOfObjects& out);

}  // namespace simp::obs
