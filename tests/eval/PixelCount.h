#pragma once
/// Pixel counting shared by the figure tests.
#include <opencv2/core.hpp>

namespace simp::eval::test {

/// Number of pixels of exactly this BGR colour.
inline int countColor(const cv::Mat3b& img, const cv::Scalar& c) {
    const cv::Vec3b v(static_cast<uchar>(c[0]), static_cast<uchar>(c[1]), static_cast<uchar>(c[2]));
    int n = 0;
    for (int r = 0; r < img.rows; ++r)
        for (int k = 0; k < img.cols; ++k) n += img(r, k) == v;
    return n;
}

}  // namespace simp::eval::test
