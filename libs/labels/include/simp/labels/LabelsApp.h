#pragma once
/// \file LabelsApp.h
/// simp-labels: Omni3D labels from a ground-truth world, posed images and 2D detections.
///   simp-labels --world W --frames FRAMES.json --detections2d DET.csv|json --out labels.json [--config INI]
///               [--iou T] [--poses poses.tum --rig rig.ini|json]

#include <simp/io/CommandLine.h>
#include <simp/labels/LabelGenerator.h>

#include <ostream>
#include <string>

namespace simp::labels {

class LabelsApp {
   public:
    /// Parses the command line (std::invalid_argument on bad input); false when --help was printed.
    bool initialize(int argc, const char* const* argv, std::ostream& out);
    int run(std::ostream& out);
    static std::string usage();
    /// The declared options (the --help text and the checks derive from them).
    static io::CommandLine commandLine();

    std::string world_path, frames_path, detections_path, out_path, config_path, poses_path, rig_path;
    LabelOptions options;
    LabelSet result;  ///< after run()
};

}  // namespace simp::labels
