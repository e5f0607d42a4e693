#include <simp/eval/Scene3D.h>
#include <simp/obs/Palette.h>
#include <simp/world/ObjectMap3D.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/stock_objects.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <stdexcept>

namespace simp::eval {
namespace {

/// A line strip through `traj`, without the segment into pose `jump` (> 0: a teleport).
mrpt::opengl::CSetOfLines::Ptr trajectoryLines(const std::vector<io::StampedPose2D>& traj, std::size_t jump, double z_m,
                                               const char* name, const obs::Rgb& color) {
    auto lines = mrpt::opengl::CSetOfLines::Create();
    for (std::size_t k = 1; k < traj.size(); ++k)
        if (k != jump) lines->appendLine(traj[k - 1].pose.x, traj[k - 1].pose.y, z_m, traj[k].pose.x, traj[k].pose.y, z_m);
    lines->setLineWidth(3.0f);
    lines->setColor_u8(color[0], color[1], color[2]);
    lines->setName(name);
    return lines;
}

}  // namespace

mrpt::opengl::COpenGLScene::Ptr buildScene(const MapLayers& l) {
    auto scene = mrpt::opengl::COpenGLScene::Create();
    if (l.floorplan && l.floorplan->getSizeX() > 0 && l.floorplan->getSizeY() > 0) {
        auto grid = mrpt::opengl::CSetOfObjects::Create();
        l.floorplan->getVisualizationInto(*grid);
        grid->setName(scene_names::kFloorplan);
        scene->insert(grid);
    }
    if (l.objects && !l.objects->objects.empty()) {
        auto objects = mrpt::opengl::CSetOfObjects::Create();
        world::appendObjectBoxes(*l.objects, *objects);
        objects->setName(scene_names::kObjects);
        scene->insert(objects);
    }
    if (l.ground_truth.size() > 1)
        scene->insert(trajectoryLines(l.ground_truth, l.ground_truth_jump, 0.05, scene_names::kGroundTruth, obs::figure_colors::kGroundTruth));
    if (l.estimate.size() > 1) scene->insert(trajectoryLines(l.estimate, 0, 0.10, scene_names::kEstimate, obs::figure_colors::kEstimate));
    if (!l.particles.empty()) {
        auto cloud = mrpt::opengl::CPointCloud::Create();
        for (const auto& p : l.particles) cloud->insertPoint(static_cast<float>(p.x), static_cast<float>(p.y), 0.05f);
        cloud->setPointSize(3.0f);
        cloud->setColor_u8(obs::figure_colors::kParticles[0], obs::figure_colors::kParticles[1], obs::figure_colors::kParticles[2]);
        cloud->setName(scene_names::kParticles);
        scene->insert(cloud);
    }
    scene->insert(mrpt::opengl::stock_objects::CornerXYZSimple(1.0f, 3.0f));
    return scene;
}

void saveScene(const mrpt::opengl::COpenGLScene& scene, const std::string& path) {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    mrpt::io::CFileGZOutputStream f;
    if (!f.open(path)) throw std::runtime_error("cannot write the 3D scene '" + path + "'");
    try {
        mrpt::serialization::archiveFrom(f) << scene;
    } catch (const std::exception& e) {
        throw std::runtime_error("error while writing the 3D scene '" + path + "': " + e.what());
    }
}

mrpt::opengl::COpenGLScene::Ptr loadScene(const std::string& path) {
    mrpt::io::CFileGZInputStream f;
    if (!std::filesystem::is_regular_file(path) || !f.open(path))
        throw std::runtime_error("cannot read the 3D scene '" + path + "'");
    auto scene = mrpt::opengl::COpenGLScene::Create();
    try {
        mrpt::serialization::archiveFrom(f) >> *scene;
    } catch (const std::exception& e) {
        throw std::runtime_error("3D scene '" + path + "' is not a readable .3Dscene: " + e.what());
    }
    return scene;
}

}  // namespace simp::eval
