#include <mrpt/core/initializer.h>
#include <mrpt/rtti/CObject.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/registerAllClasses.h>

// Loading libsimp_obs.so registers the classes, so MRPT's own tools (rawlog-edit --plugins,
// RawLogViewer -l) can deserialize them.
MRPT_INITIALIZER(registerAllClasses_simp_obs) { simp::obs::registerAllClasses(); }

namespace simp::obs {
void registerAllClasses() { mrpt::rtti::registerClass(CLASS_ID(CObservationObjects3D)); }
}  // namespace simp::obs
