/// \file LabelsApp.cpp
#include <simp/io/StrictIni.h>
#include <simp/io/StrictNumber.h>
#include <simp/io/ToolArgs.h>
#include <simp/labels/LabelsApp.h>
#include <simp/world/World.h>

#include <filesystem>
#include <stdexcept>

namespace simp::labels {

namespace fs = std::filesystem;

std::string LabelsApp::usage() {
    return "Usage: simp-labels --world W --frames FRAMES.json --detections2d DET.csv|DET.json --out labels.json\n"
           "                   [--config INI] [--iou T] [--poses poses.tum --rig rig.ini|json]\n"
           "Projects the world's boxes into each posed image (Eq. reprojection), computes truncation and\n"
           "visibility (boxes z-buffer + floor-plan walls), matches 2D detections by class and 2D IoU and\n"
           "writes Omni3D JSON for Cube R-CNN (doc/labels.md). --world: a world directory (walls used) or an\n"
           "objects.json file (no walls). --poses/--rig: images of FRAMES.json given by \"camera\" and\n"
           "\"timestamp\" get their pose and K from the robot poses and the camera rig.\n";
}

bool LabelsApp::initialize(int argc, const char* const* argv, std::ostream& out) {
    const io::ToolArgs a = io::parseToolArgs(argc, argv, {"world", "frames", "detections2d", "out"}, {"config", "iou", "poses", "rig"});
    if (a.help) {
        out << usage();
        return false;
    }
    world_path = a.get("world"), frames_path = a.get("frames"), detections_path = a.get("detections2d");
    out_path = a.get("out");
    if (a.has("poses") != a.has("rig")) throw std::invalid_argument("--poses and --rig go together");
    if (a.has("poses")) poses_path = a.get("poses"), rig_path = a.get("rig");
    if (a.has("config")) {
        config_path = a.get("config");
        io::StrictIni(config_path).loadChecked([&](const io::StrictIni& ini) { options.loadFromConfigFile(ini, "simp-labels"); });
    }
    if (a.has("iou")) options.iou_threshold = io::parseNumber(a.get("iou"), "--iou", 0, 1);
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
    CameraRig rig;
    if (!poses_path.empty()) poses = io::readTum(poses_path), rig = loadCameraRig(rig_path);
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
