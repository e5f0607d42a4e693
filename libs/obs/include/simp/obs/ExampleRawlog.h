#pragma once
/// \file ExampleRawlog.h
/// A small, deterministic rawlog of 3D-object observations: for checking MRPT's tools
/// with the plugin and for tests, on any machine, without external data.

#include <cstdint>
#include <string>

namespace simp::obs {

struct ExampleRawlogParams {
    std::size_t frames = 20;        ///< sensory frames (time steps)
    std::size_t cameras = 4;        ///< observations per frame, labels CAMERA_0..CAMERA_{n-1}
    std::size_t detections = 3;     ///< detections per observation
    double frame_period_s = 0.2;    ///< time between frames
    std::uint64_t seed = 1;         ///< all numbers derive from it
};

/// Writes `path` (MRPT rawlog, actions + sensory-frames format, uncompressed) and returns the number
/// of observations written. Throws std::runtime_error naming the file when it cannot write.
/// Most frames and cameras of an example rawlog (100000 frames of 4 cameras x 3 detections: ~350 MB).
constexpr std::size_t kMaxExampleFrames = 100000;
constexpr std::size_t kMaxExampleCameras = 64;

/// \throw std::invalid_argument naming the field unless 1 <= frames <= kMaxExampleFrames,
///        1 <= cameras <= kMaxExampleCameras, detections <= limits::kMaxDetectionsPerFrame.
void validateExampleRawlogParams(const ExampleRawlogParams& params);

std::size_t writeExampleRawlog(const std::string& path, const ExampleRawlogParams& params);

}  // namespace simp::obs
