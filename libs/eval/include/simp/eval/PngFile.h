#pragma once
/// \file PngFile.h
/// Writing a figure: the one PNG writer of every app.

#include <opencv2/core.hpp>

#include <string>

namespace simp::eval {

/// Writes a PNG, creating the parent folders. \throw std::runtime_error naming the file.
void writePng(const std::string& path, const cv::Mat& image);

}  // namespace simp::eval
