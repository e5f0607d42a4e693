#include <mrpt/opengl/CSetOfObjects.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/ObjectStyle.h>
#include <simp/world/ObjectMap3D.h>

namespace simp::maps {

std::array<std::uint8_t, 3> CObjectMap::classColor(int class_id) { return obs::classColorRgb(class_id); }

void CObjectMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const {
    if (!genericMapParams.enableSaveAs3DObject) return;
    world::appendObjectBoxes(m_data, outObj);
}

}  // namespace simp::maps
