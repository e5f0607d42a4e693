#include <mrpt/math/wrap2pi.h>
#include <simp/io/StrictNumber.h>
#include <simp/io/Tum.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace simp::io {
namespace {
// Same bound as simp::obs::limits::kMaxCoordinate_m (libs/io does not depend on libs/obs).
constexpr double kMaxTumCoordinate_m = 1e4;
// Unix time up to the year 2286; larger stamps lose sub-millisecond precision as doubles.
constexpr double kMaxTumTime_s = 1e10;
}  // namespace

std::vector<StampedPose2D> readTum(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("TUM file '" + path + "': cannot open for reading");
    std::vector<StampedPose2D> out;
    std::string line;
    for (int line_no = 1; std::getline(f, line); ++line_no) {
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::istringstream s(line);
        double v[8];
        int n = 0;
        std::string tok;
        while (s >> tok) {
            if (n == 8) throw std::runtime_error("TUM file '" + path + "' line " + std::to_string(line_no) +
                                                 ": more than 8 columns (expected t x y z qx qy qz qw)");
            const auto x = parseFiniteNumber(tok);
            if (!x)
                throw std::runtime_error("TUM file '" + path + "' line " + std::to_string(line_no) + ": '" + tok +
                                         "' is not a finite number");
            v[n] = *x;
            ++n;
        }
        if (n != 8)
            throw std::runtime_error("TUM file '" + path + "' line " + std::to_string(line_no) + ": " +
                                     std::to_string(n) + " columns, expected 8 (t x y z qx qy qz qw)");
        // Poses of a building (doc/formats.md limits): a coordinate beyond it is a broken file.
        for (int k = 1; k <= 3; ++k)
            if (std::abs(v[k]) > kMaxTumCoordinate_m)
                throw std::runtime_error("TUM file '" + path + "' line " + std::to_string(line_no) + ": coordinate " +
                                         std::to_string(v[k]) + " m beyond the maximum 1e4 m");
        if (std::abs(v[0]) > kMaxTumTime_s)
            throw std::runtime_error("TUM file '" + path + "' line " + std::to_string(line_no) + ": time stamp " +
                                     std::to_string(v[0]) + " s beyond the maximum |t| = 1e10 s");
        const double qx = v[4], qy = v[5], qz = v[6], qw = v[7];
        const double qn = std::sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
        if (qn < 1e-9)
            throw std::runtime_error("TUM file '" + path + "' line " + std::to_string(line_no) + ": zero quaternion");
        // yaw of the rotation (ZYX convention), valid for planar and 3D poses alike
        const double yaw = std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
        if (!out.empty() && v[0] <= out.back().t_s)
            throw std::runtime_error("TUM file '" + path + "' line " + std::to_string(line_no) +
                                     ": time stamps must increase");
        out.push_back({v[0], mrpt::math::TPose2D(v[1], v[2], yaw)});
    }
    return out;
}

std::string tumHeader() { return "# t x y z qx qy qz qw\n"; }

std::string tumLine(const StampedPose2D& p) {
    std::ostringstream f;
    const double h = 0.5 * p.pose.phi;
    f << std::fixed << std::setprecision(6) << p.t_s << " " << std::setprecision(6) << p.pose.x << " " << p.pose.y
      << " 0 0 0 " << std::setprecision(9) << std::sin(h) << " " << std::cos(h) << "\n";
    return f.str();
}

void writeTum(const std::string& path, const std::vector<StampedPose2D>& poses) {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    std::ofstream f(path);
    if (!f) throw std::runtime_error("TUM file '" + path + "': cannot open for writing");
    f << tumHeader();
    for (const auto& p : poses) f << tumLine(p);
    if (!f) throw std::runtime_error("TUM file '" + path + "': write failed");
}

bool interpolatePose(const std::vector<StampedPose2D>& traj, double t_s, mrpt::math::TPose2D& out) {
    if (traj.empty() || t_s < traj.front().t_s || t_s > traj.back().t_s) return false;
    const auto it = std::lower_bound(traj.begin(), traj.end(), t_s,
                                     [](const StampedPose2D& p, double t) { return p.t_s < t; });
    if (it->t_s == t_s || it == traj.begin()) {
        out = it->pose;
        return true;
    }
    const auto& a = *(it - 1);
    const auto& b = *it;
    const double u = (t_s - a.t_s) / (b.t_s - a.t_s);
    out.x = a.pose.x + u * (b.pose.x - a.pose.x);
    out.y = a.pose.y + u * (b.pose.y - a.pose.y);
    out.phi = mrpt::math::wrapToPi(a.pose.phi + u * mrpt::math::wrapToPi(b.pose.phi - a.pose.phi));
    return true;
}

}  // namespace simp::io
