#pragma once
/// \file ImageLimits.h
/// Rasters of a world directory (floor plan, rooms.png) are untrusted: a 100 KB PNG can declare
/// 60000 x 60000 px and decode to gigabytes. Their declared size is read from the file header
/// and checked *before* OpenCV decodes them (doc/formats.md, "Limits of untrusted input").

#include <cstdint>
#include <optional>
#include <string>

namespace simp::world {

/// Most pixels of a floor plan or room raster: 25 Mpx (250 m x 250 m at 5 cm/px), about
/// 250 MB while loading (the grey image as doubles plus MRPT's grid).
constexpr std::uint64_t kMaxRasterPixels = 25'000'000;
/// Floor-plan resolution range, m per pixel.
constexpr double kMinResolution_m = 1e-3;
constexpr double kMaxResolution_m = 10.0;

struct ImageSize {
    std::uint64_t width = 0, height = 0;
};

/// Width and height declared by a PNG or PNM (P1..P6) header; nullopt for other formats or a
/// header that cannot be parsed (OpenCV then reports it).
std::optional<ImageSize> declaredImageSize(const std::string& path);

/// Throws std::runtime_error("PATH: image of W x H px exceeds the maximum of N pixels ...")
/// when the declared (or, for other formats, the decoded) size is too large.
void checkRasterSize(const std::string& path, const ImageSize& size);
void checkDeclaredRasterSize(const std::string& path);

}  // namespace simp::world
