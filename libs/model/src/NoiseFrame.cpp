#include <simp/model/NoiseFrame.h>

#include <cmath>

namespace simp::model {

double classNoiseFrameYaw(const geometry::Box3D& box) {
    const double yaw = geometry::yawOf(box);
    return box.size.x() > box.size.y() ? yaw + M_PI / 2 : yaw;
}

double noiseFrameYaw(const geometry::Box3D& box, NoiseSource source) {
    return source == NoiseSource::Object ? geometry::yawOf(box) : classNoiseFrameYaw(box);
}

}  // namespace simp::model
