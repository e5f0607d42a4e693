// libFuzzer target: the detector imports. First byte even: Cube R-CNN / Omni3D predictions JSON;
// odd: the ROS detections CSV. Both are then turned into rawlog frames with a fixed rig and
// poses (the path where an empty poses list once crashed).
#include <simp/io/Tum.h>
#include <simp/detector_io/CameraRig.h>
#include <simp/detector_io/DetectionSet.h>
#include <simp/detector_io/Omni3DPredictions.h>
#include <simp/detector_io/RosDetectionsCsv.h>
#include <simp/obs/ObjectClasses.h>

#include "FuzzUtil.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    static const simp::detector_io::CameraRig rig = [] {
        const std::string ini =
            "[rig]\ncameras = CAMERA_0\n[CAMERA_0]\nx=0.1\ny=0\nz=0.6\nyaw_rad=0\nfx=380\nfy=380\ncx=320\ncy=240\n"
            "width=640\nheight=480\n";
        const auto path = simp_fuzz::writeInput("rig.ini", reinterpret_cast<const std::uint8_t*>(ini.data()), ini.size());
        return simp::detector_io::loadCameraRig(path);
    }();
    const std::vector<simp::io::StampedPose2D> poses = {{0.0, {0, 0, 0}}, {100.0, {1, 0, 0}}};
    simp_fuzz::expectNoCrash([&] {
        simp::detector_io::DetectionSet set;
        if (data[0] % 2 == 0)
            set = simp::detector_io::readOmni3DPredictions(simp_fuzz::writeInput("predictions.json", data + 1, size - 1));
        else
            set = simp::detector_io::readRosDetectionsCsv(simp_fuzz::writeInput("detections.csv", data + 1, size - 1),
                                                     simp::obs::defaultClassNames(), rig);
        simp::detector_io::framesFromDetections(set, poses, rig, "fuzz");
        simp::detector_io::framesFromDetections(set, {}, rig, "fuzz");
    });
    return 0;
}
