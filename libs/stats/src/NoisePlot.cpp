/// \file NoisePlot.cpp
#include <simp/stats/NoisePlot.h>

#include <Eigen/Eigenvalues>
#include <opencv2/imgproc.hpp>
#include <simp/eval/FigureColors.h>
#include <simp/eval/PngFile.h>

#include <algorithm>
#include <cmath>

namespace simp::stats {

void writeNoisePng(const std::string& path, const Histogram2D& h, const NoiseFit& fit, const std::string& title,
                   int pixels_per_cell) {
    const int s = std::max(1, pixels_per_cell);
    const int nx = static_cast<int>(h.counts.rows()), ny = static_cast<int>(h.counts.cols());
    const double max_count = std::max(1.0, h.counts.maxCoeff());
    cv::Mat1b grey(ny, nx);
    for (int ix = 0; ix < nx; ++ix)
        for (int iy = 0; iy < ny; ++iy)  // image row 0 = largest y (y up)
            grey(ny - 1 - iy, ix) = static_cast<unsigned char>(std::lround(255.0 * h.counts(ix, iy) / max_count));
    cv::Mat heat, big;
    cv::applyColorMap(grey, heat, cv::COLORMAP_VIRIDIS);
    cv::resize(heat, big, cv::Size(nx * s, ny * s), 0, 0, cv::INTER_NEAREST);
    const double px_per_m = s / h.cell_m;
    const auto toPixel = [&](const Eigen::Vector2d& p) {
        return cv::Point2d((p.x() - h.x_min_m) * px_per_m, (ny * h.cell_m - (p.y() - h.y_min_m)) * px_per_m);
    };
    const cv::Point2d origin = toPixel(Eigen::Vector2d::Zero());
    namespace fc = obs::figure_colors;
    cv::drawMarker(big, origin, eval::toBgr(fc::kSigma3), cv::MARKER_CROSS, 3 * s, 1);
    // Ellipses: semi-axes k sqrt(lambda_i) along the eigenvectors of Sigma.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(fit.model.cov_m2);
    const Eigen::Vector2d ev = es.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    const Eigen::Vector2d axis = es.eigenvectors().col(1);
    const double angle_deg = -std::atan2(axis.y(), axis.x()) * 180.0 / M_PI;  // image y is down
    const cv::Point2d c = toPixel(fit.model.mean_m);
    const cv::Scalar colours[3] = {eval::toBgr(fc::kSigma1), eval::toBgr(fc::kSigma2), eval::toBgr(fc::kSigma3)};
    for (int k = 1; k <= 3; ++k)
        cv::ellipse(big, cv::RotatedRect(c, cv::Size2f(static_cast<float>(2 * k * ev(1) * px_per_m),
                                                      static_cast<float>(2 * k * ev(0) * px_per_m)),
                                         static_cast<float>(angle_deg)),
                    colours[k - 1], 1, cv::LINE_AA);
    cv::putText(big, title, cv::Point(4, 14), cv::FONT_HERSHEY_SIMPLEX, 0.45, eval::toBgr(fc::kSigma3), 1, cv::LINE_AA);
    eval::writePng(path, big);
}

}  // namespace simp::stats
