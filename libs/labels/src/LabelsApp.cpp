/// \file LabelsApp.cpp
#include <simp/io/StrictIni.h>
#include <simp/io/CommandLine.h>
#include <simp/labels/LabelsApp.h>
#include <simp/world/World.h>

#include <filesystem>
#include <stdexcept>

namespace simp::labels {

namespace fs = std::filesystem;

io::CommandLine LabelsApp::commandLine() {
    io::CommandLine c("simp-labels",
                      "Projects the world's boxes into each posed image (Eq. reprojection), computes truncation and\n"
                      "visibility (boxes z-buffer + floor-plan walls), matches 2D detections by class and 2D IoU and\n"
                      "writes Omni3D JSON for Cube R-CNN (doc/labels.md).");
    c.required("world", "W", "a world directory (walls used) or an objects.json file (no walls)")
        .required("frames", "FRAMES.json", "the posed images")
        .required("detections2d", "DET.csv|DET.json", "2D detections")
        .required("out", "labels.json", "the Omni3D labels to write")
        .option("config", "INI", ".ini with a [simp-labels] section")
        .option("iou", "T", "2D IoU threshold in [0, 1], overrides [simp-labels] iou_threshold")
        .option("poses", "poses.tum", "robot poses: images of FRAMES.json given by \"camera\" and \"timestamp\" get\n"
                                      "their pose and K from the robot poses and the camera rig (with --rig)")
        .option("rig", "rig.ini|rig.json", "the camera rig (with --poses)");
    return c;
}

std::string LabelsApp::usage() { return commandLine().help(); }

bool LabelsApp::initialize(int argc, const char* const* argv, std::ostream& out) {
    io::CommandLine a = commandLine();
    if (!a.parse(argc, argv, out)) return false;
    world_path = a.value("world"), frames_path = a.value("frames"), detections_path = a.value("detections2d");
    out_path = a.value("out");
    if (a.has("poses") != a.has("rig")) throw std::invalid_argument("--poses and --rig go together");
    if (a.has("poses")) poses_path = a.value("poses"), rig_path = a.value("rig");
    if (a.has("config")) {
        config_path = a.value("config");
        io::StrictIni(config_path).loadChecked([&](const io::StrictIni& ini) { options.loadFromConfigFile(ini, "simp-labels"); });
    }
    if (const auto iou = a.number("iou", 0, 1)) options.iou_threshold = *iou;
    options.validate();
    return true;
}

int LabelsApp::run(std::ostream& out) {
    options.dumpToTextStream(out);
    world::World w;
    const bool has_walls = fs::is_directory(world_path);
    if (has_walls)
        w = world::loadWorld(world_path);
    else
        w.objects = world::loadObjectMap(world_path);
    std::vector<io::StampedPose2D> poses;
    detector_io::CameraRig rig;
    if (!poses_path.empty()) poses = io::readTum(poses_path), rig = detector_io::loadCameraRig(rig_path);
    const auto images = readCameraFrames(frames_path, poses_path.empty() ? nullptr : &rig,
                                         poses_path.empty() ? nullptr : &poses);
    const auto dets = readDetections2D(detections_path, w.objects.class_names);
    out << images.size() << " images, " << dets.size() << " 2D detections, " << w.objects.objects.size()
        << " ground-truth objects" << (has_walls ? "" : " (no floor plan: walls ignored)") << "\n";
    result = generateLabels(w.objects, has_walls ? &w.floorplan : nullptr, images, dets, options);
    writeOmni3DLabels(out_path, result);
    out << "wrote " << out_path << ": " << result.annotations.size() << " annotations; " << result.detections_unmatched
        << " 2D detections without a 3D box, " << result.detections_unknown_image << " with an unknown image id\n";
    return 0;
}

}  // namespace simp::labels
