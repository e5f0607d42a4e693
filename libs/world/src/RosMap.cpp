/// \file RosMap.cpp
/// ROS map_server floor plans (yaml + image) <-> mrpt::maps::COccupancyGridMap2D.
/// Geometry: the image's bottom-left pixel corner is at `origin`; image row 0 is the top
/// (max y) while MRPT's grid row cy = 0 is the bottom (min y), so cy = rows - 1 - row.

#include <mrpt/containers/yaml.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <simp/obs/InputLimits.h>
#include <simp/world/ImageLimits.h>
#include <simp/world/World.h>
#include <simp/world/YamlText.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace simp::world {

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& what) {
    throw std::runtime_error(file + ": " + what);
}

double yamlNumber(const mrpt::containers::yaml& y, const std::string& key, const std::string& file) {
    if (!y.has(key)) fail(file, key + ": missing");
    double v = 0;
    try {
        v = y[key].as<double>();
    } catch (const std::exception&) {
        fail(file, key + ": expected a number");
    }
    if (!std::isfinite(v)) fail(file, key + ": expected a finite number");
    return v;
}

/// Shortest text that reads back to the same float (the grid stores floats).
std::string floatText(float v) {
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof(buf), v);
    return std::string(buf, res.ptr);
}

/// Gives access to the protected extent of the MRPT grid (a pointer to a protected base member
/// formed in a derived class is a legal way to reach it).
struct GridExtentAccess : mrpt::maps::COccupancyGridMap2D {
    static void set(mrpt::maps::COccupancyGridMap2D& g, float x_min, float x_max, float y_min, float y_max) {
        g.*(&GridExtentAccess::m_xMin) = x_min;
        g.*(&GridExtentAccess::m_xMax) = x_max;
        g.*(&GridExtentAccess::m_yMin) = y_min;
        g.*(&GridExtentAccess::m_yMax) = y_max;
    }
};

}  // namespace

RosMapYaml readRosMapYaml(const std::string& yaml_path) {
    if (!std::filesystem::exists(yaml_path)) fail(yaml_path, "file not found");
    const std::string text = readYamlText(yaml_path);  // before libfyaml: YamlText.h
    mrpt::containers::yaml y;
    try {
        y = mrpt::containers::yaml::FromText(text);
    } catch (const std::exception& e) {
        fail(yaml_path, std::string("invalid YAML: ") + e.what());
    }
    if (!y.isMap()) fail(yaml_path, "expected a YAML map with the map_server keys");
    RosMapYaml m;
    if (!y.has("image")) fail(yaml_path, "image: missing");
    const std::string image = y["image"].as<std::string>();
    if (image.empty()) fail(yaml_path, "image: empty");
    const std::filesystem::path img(image);
    m.image_path = img.is_absolute() ? img.string()
                                     : (std::filesystem::path(yaml_path).parent_path() / img).string();
    m.resolution_m = yamlNumber(y, "resolution", yaml_path);
    if (m.resolution_m <= 0) fail(yaml_path, "resolution: expected a positive number (m/pixel)");
    if (m.resolution_m < kMinResolution_m || m.resolution_m > kMaxResolution_m)
        fail(yaml_path, "resolution: " + std::to_string(m.resolution_m) + " m/pixel is outside [" +
                            std::to_string(kMinResolution_m) + ", " + std::to_string(kMaxResolution_m) + "]");
    if (!y.has("origin")) fail(yaml_path, "origin: missing");
    std::vector<double> origin;
    try {
        origin = y["origin"].toStdVector<double>();
    } catch (const std::exception&) {
        fail(yaml_path, "origin: expected [x, y, yaw]");
    }
    if (origin.size() != 3 || !std::isfinite(origin[0]) || !std::isfinite(origin[1]) || !std::isfinite(origin[2]))
        fail(yaml_path, "origin: expected 3 finite numbers [x, y, yaw]");
    if (std::abs(origin[0]) > obs::limits::kMaxCoordinate_m || std::abs(origin[1]) > obs::limits::kMaxCoordinate_m)
        fail(yaml_path, "origin: coordinates beyond the maximum " + std::to_string(obs::limits::kMaxCoordinate_m) + " m");
    m.origin_x_m = origin[0];
    m.origin_y_m = origin[1];
    m.origin_yaw_rad = origin[2];
    if (m.origin_yaw_rad != 0.0) fail(yaml_path, "origin: a non-zero yaw is not supported (MRPT grids are axis-aligned)");
    m.occupied_thresh = yamlNumber(y, "occupied_thresh", yaml_path);
    m.free_thresh = yamlNumber(y, "free_thresh", yaml_path);
    if (!(0 <= m.free_thresh && m.free_thresh <= m.occupied_thresh && m.occupied_thresh <= 1))
        fail(yaml_path, "free_thresh/occupied_thresh: expected 0 <= free_thresh <= occupied_thresh <= 1");
    if (y.has("negate")) {
        const double n = yamlNumber(y, "negate", yaml_path);
        if (n != 0 && n != 1) fail(yaml_path, "negate: expected 0 or 1");
        m.negate = (n == 1);
    }
    if (y.has("mode")) m.mode = y["mode"].as<std::string>();
    if (m.mode != "trinary" && m.mode != "scale")
        fail(yaml_path, "mode: '" + m.mode + "' not supported (trinary or scale)");
    return m;
}

void setGridExactly(mrpt::maps::COccupancyGridMap2D& grid, double x_min_m, double y_min_m, unsigned size_x,
                    unsigned size_y, double resolution_m, float default_occupancy) {
    if (size_x == 0 || size_y == 0 || !(resolution_m > 0))
        throw std::invalid_argument("setGridExactly: empty grid or non-positive resolution");
    const auto res = static_cast<float>(resolution_m);
    // setSize rounds the limits to multiples of the resolution; the cell count is what we ask.
    grid.setSize(0.0f, res * static_cast<float>(size_x), 0.0f, res * static_cast<float>(size_y), res,
                 default_occupancy);
    if (grid.getSizeX() != size_x || grid.getSizeY() != size_y)
        throw std::runtime_error("setGridExactly: MRPT produced an unexpected grid size");
    GridExtentAccess::set(grid, static_cast<float>(x_min_m), static_cast<float>(x_min_m + resolution_m * size_x),
                          static_cast<float>(y_min_m), static_cast<float>(y_min_m + resolution_m * size_y));
}

void loadRosMap(const std::string& yaml_path, mrpt::maps::COccupancyGridMap2D& grid) {
    const RosMapYaml m = readRosMapYaml(yaml_path);
    if (!std::filesystem::exists(m.image_path)) fail(yaml_path, "image: file '" + m.image_path + "' not found");
    checkDeclaredRasterSize(m.image_path);  // before decoding: a small PNG can declare gigapixels
    cv::Mat img = cv::imread(m.image_path, cv::IMREAD_UNCHANGED);
    if (img.empty()) fail(m.image_path, "cannot read the image (referenced by " + yaml_path + ")");
    checkRasterSize(m.image_path, {static_cast<std::uint64_t>(img.cols), static_cast<std::uint64_t>(img.rows)});
    if (img.depth() == CV_16U) img.convertTo(img, CV_8U, 1.0 / 257.0);
    if (img.depth() != CV_8U) fail(m.image_path, "expected an 8-bit or 16-bit image");
    // map_server averages the colour channels (alpha ignored here). Read per pixel from the 8-bit
    // image: a double copy of the raster cost 8 bytes/px (200 MB for a 35 KB PNG of 25 Mpx).
    const int nch = img.channels();
    if (nch != 1 && nch != 3 && nch != 4) fail(m.image_path, "unsupported number of channels");
    const int rows = img.rows, cols = img.cols;
    setGridExactly(grid, m.origin_x_m, m.origin_y_m, static_cast<unsigned>(cols), static_cast<unsigned>(rows),
                   m.resolution_m, 0.5f);
    for (int r = 0; r < rows; ++r) {
        const int cy = rows - 1 - r;
        const uchar* row = img.ptr<uchar>(r);
        for (int c = 0; c < cols; ++c) {
            const uchar* px = row + static_cast<std::ptrdiff_t>(c) * nch;
            const double v = nch == 1 ? double(px[0]) : (double(px[0]) + double(px[1]) + double(px[2])) / 3.0;
            const double p = m.negate ? v / 255.0 : (255.0 - v) / 255.0;  // occupancy probability
            float occ = 0.5f;
            if (p > m.occupied_thresh) occ = 1.0f;
            else if (p < m.free_thresh) occ = 0.0f;
            else if (m.mode == "scale" && m.occupied_thresh > m.free_thresh)
                occ = static_cast<float>((p - m.free_thresh) / (m.occupied_thresh - m.free_thresh));
            // MRPT's cell value is the probability of being FREE (0 = occupied, 1 = free).
            grid.setCell(c, cy, 1.0f - occ);
        }
    }
}

void saveRosMap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& yaml_path) {
    const unsigned cols = grid.getSizeX(), rows = grid.getSizeY();
    if (cols == 0 || rows == 0) fail(yaml_path, "cannot save an empty grid");
    const std::filesystem::path yp(yaml_path);
    if (yp.has_parent_path()) std::filesystem::create_directories(yp.parent_path());
    const std::filesystem::path png = yp.parent_path() / (yp.stem().string() + ".png");
    cv::Mat1b img(static_cast<int>(rows), static_cast<int>(cols));
    for (unsigned cy = 0; cy < rows; ++cy)
        for (unsigned cx = 0; cx < cols; ++cx) {
            const float occ = 1.0f - grid.getCell(static_cast<int>(cx), static_cast<int>(cy));  // MRPT stores P(free)
            const uchar v = occ >= static_cast<float>(kWrittenOccupiedThresh)
                                ? 0
                                : (occ <= static_cast<float>(kWrittenFreeThresh) ? 254 : 205);
            img(static_cast<int>(rows - 1 - cy), static_cast<int>(cx)) = v;
        }
    if (!cv::imwrite(png.string(), img)) fail(png.string(), "cannot write the image");
    std::ofstream out(yaml_path);
    if (!out) fail(yaml_path, "cannot open for writing");
    out << "image: " << png.filename().string() << "\n"
        << "resolution: " << floatText(grid.getResolution()) << "\n"
        << "origin: [" << floatText(grid.getXMin()) << ", " << floatText(grid.getYMin()) << ", 0.0]\n"
        << "negate: 0\n"
        << "occupied_thresh: " << kWrittenOccupiedThresh << "\n"
        << "free_thresh: " << kWrittenFreeThresh << "\n";
    if (!out) fail(yaml_path, "write failed");
}

}  // namespace simp::world
