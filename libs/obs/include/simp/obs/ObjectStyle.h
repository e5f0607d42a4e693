#pragma once
/// \file ObjectStyle.h
/// How an object looks in the 3D views (the observation in RawLogViewer, the object map's
/// getVisualizationInto, the .3Dscene files of simp::eval::buildScene): a labelled wireframe box
/// in its class colour (simp/obs/Palette.h, the colour it has in the 2D figures too).

#include <mrpt/opengl/CSetOfObjects.h>
#include <simp/geometry/Box3D.h>
#include <simp/obs/Palette.h>

#include <string>

namespace simp::obs {

/// Appends to `out` a wireframe mrpt::opengl::CBox of `box` (in `out`'s frame) in `color` and an
/// mrpt::opengl::CText `label` 0.1 m above the box's top, same colour.
void appendLabelledBox(const geometry::Box3D& box, const Rgb& color, const std::string& label,
                       mrpt::opengl::CSetOfObjects& out);

}  // namespace simp::obs
