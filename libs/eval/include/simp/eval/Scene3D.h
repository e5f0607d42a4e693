#pragma once
/// \file Scene3D.h
/// The 3D scene of a run for MRPT's SceneViewer3D (`.3Dscene`): the one scene builder that
/// simp-localize --3dscene and simp-map --3dscene use (doc/evaluation.md).

#include <mrpt/opengl/COpenGLScene.h>
#include <simp/eval/MapLayers.h>

#include <string>

namespace simp::eval {

/// Names of the scene's top-level objects (mrpt::opengl::COpenGLScene::getByName).
namespace scene_names {
inline constexpr const char* kFloorplan = "floorplan";        ///< CSetOfObjects (COccupancyGridMap2D's view)
inline constexpr const char* kObjects = "objects";            ///< CSetOfObjects: a CBox + a CText per object
inline constexpr const char* kGroundTruth = "ground_truth";   ///< CSetOfLines, green
inline constexpr const char* kEstimate = "estimate";          ///< CSetOfLines, red
inline constexpr const char* kParticles = "particles";        ///< CPointCloud, blue
}  // namespace scene_names

/// One scene in the world frame (z up, m): the floor plan as MRPT draws an occupancy grid
/// (a textured plane at z = 0), the object boxes coloured by class with text labels
/// (simp::world::appendObjectBoxes), the ground-truth and estimated trajectories as line strips
/// 5 cm and 10 cm above the floor, the particles as points 5 cm above it, and XYZ axes. Layers
/// that are null or empty are left out.
mrpt::opengl::COpenGLScene::Ptr buildScene(const MapLayers& layers);

/// Writes `scene` as SceneViewer3D reads it: gzip-compressed MRPT serialization
/// (mrpt::io::CFileGZOutputStream). Creates the parent folders.
/// \throw std::runtime_error naming the file when it cannot be written.
void saveScene(const mrpt::opengl::COpenGLScene& scene, const std::string& path);

/// Reads a `.3Dscene` file back. \throw std::runtime_error naming the file.
mrpt::opengl::COpenGLScene::Ptr loadScene(const std::string& path);

}  // namespace simp::eval
