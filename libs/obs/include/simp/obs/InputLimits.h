#pragma once
/// \file InputLimits.h
/// Sanity limits every reader of untrusted input applies (rawlogs, object maps, world
/// directories, detector files). A value beyond them is a corrupted or hostile file, never a
/// real office: rejecting it early keeps memory and run time bounded by the input's size
/// (doc/formats.md, "Limits of untrusted input").

#include <cstddef>
#include <cstdint>

namespace simp::obs::limits {

/// |x|, |y|, |z| of any position (box centre, camera or robot pose), m. A building is < 1 km.
constexpr double kMaxCoordinate_m = 1e4;
/// Largest box side (W, H, L or an object map's size_m), m: bigger than any furniture or room.
constexpr double kMaxBoxSide_m = 100.0;
/// Longest name (class name, sensor label, option text) in a binary file, bytes.
constexpr std::size_t kMaxNameLength = 1024;
/// Most classes in a label set (the paper's detector has 14; Omni3D 98).
constexpr std::size_t kMaxClasses = 1000;
/// Most detections in one camera frame.
constexpr std::size_t kMaxDetectionsPerFrame = 10000;
/// Most objects in one object map (a floor of a large building holds a few thousand).
constexpr std::size_t kMaxMapObjects = 1000000;
/// Largest image side, px (camera images and floor-plan rasters).
constexpr std::uint32_t kMaxImageSide_px = 65536;
/// Most Thrun motion-model particles the robot movements of one rawlog entry may draw together (MRPT's
/// default is 300 per movement; MRPT 2.5 allocates 32 bytes per particle at deserialization, before
/// any check).
constexpr std::uint32_t kMaxThrunParticles = 100000;

}  // namespace simp::obs::limits
