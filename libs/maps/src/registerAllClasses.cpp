#include <mrpt/core/initializer.h>
#include <mrpt/rtti/CObject.h>
#include <simp/maps/CObjectMap.h>
#include <simp/maps/registerAllClasses.h>

// Loading libsimp_maps.so registers CObjectMap with MRPT's RTTI (deserialization) and, through
// MAP_DEFINITION_REGISTER in CObjectMap.cpp, as the map kind "semanticObjectMap" of .ini files.
MRPT_INITIALIZER(registerAllClasses_simp_maps) { simp::maps::registerAllClasses(); }

namespace simp::maps {
void registerAllClasses() { mrpt::rtti::registerClass(CLASS_ID(CObjectMap)); }
}  // namespace simp::maps
