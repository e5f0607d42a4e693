#include <simp/world/NoiseFrame.h>

#include <cmath>

namespace simp::world {

double classNoiseFrameYaw(const geometry::Box3D& box) {
    const double yaw = geometry::yawOf(box);
    return box.size.x() > box.size.y() ? yaw + M_PI / 2 : yaw;
}

double noiseFrameYawOf(const MapObject& o) { return o.noise ? geometry::yawOf(o.box) : classNoiseFrameYaw(o.box); }

}  // namespace simp::world
