/// \file RosDetectionsCsv.cpp
#include <simp/detector_io/Omni3DBox.h>
#include <simp/io/StrictNumber.h>
#include <simp/detector_io/RosDetectionsCsv.h>

#include <algorithm>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace simp::detector_io {

namespace {

[[noreturn]] void failAt(const std::string& file, std::size_t line, const std::string& what) {
    throw std::runtime_error(file + ": line " + std::to_string(line) + ": " + what);
}

std::string trimBlanks(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

double toNumber(const std::string& field, const std::string& file, std::size_t line, std::size_t column) {
    const std::string f = trimBlanks(field);
    const auto x = io::parseFiniteNumber(f);
    if (!x) failAt(file, line, "column " + std::to_string(column) + ": expected a finite number, got '" + f + "'");
    return *x;
}

}  // namespace

DetectionSet readRosDetectionsCsv(const std::string& path, const std::vector<std::string>& class_names,
                                  const CameraRig& rig) {
    if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": file not found");
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open for reading");
    DetectionSet set;
    set.class_names = class_names;
    std::string raw;
    std::size_t line_no = 0;
    while (std::getline(in, raw)) {
        ++line_no;
        const std::string line = trimBlanks(raw);
        if (line.empty() || line[0] == '#' || (line_no == 1 && line.rfind("timestamp", 0) == 0)) continue;
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
        if (!line.empty() && line.back() == ',') f.emplace_back();
        if (f.size() < 2 || (f.size() - 2) % 26 != 0)
            failAt(path, line_no, "wrong column count " + std::to_string(f.size()) +
                                      " (expected 2 + 26 N: timestamp, camera, then 8 corners x 3, confidence, class per object)");
        DetectionImage im;
        im.id = static_cast<std::int64_t>(set.images.size());
        im.timestamp_s = toNumber(f[0], path, line_no, 1);
        const std::string cam = trimBlanks(f[1]);
        if (rig.indexOf(cam) >= 0) {
            im.camera = cam;
        } else {
            char* end = nullptr;
            const long idx = std::strtol(cam.c_str(), &end, 10);
            if (cam.empty() || *end != '\0' || idx < 0 || idx >= static_cast<long>(rig.cameras.size()))
                failAt(path, line_no, "column 2: unknown camera '" + cam + "' (not a rig camera name or index)");
            im.camera = rig.cameras[static_cast<std::size_t>(idx)].name;
        }
        for (std::size_t k = 0; 2 + 26 * k < f.size(); ++k) {
            const std::size_t base = 2 + 26 * k;
            std::array<Eigen::Vector3d, 8> corners;
            for (std::size_t c = 0; c < 8; ++c)
                for (std::size_t a = 0; a < 3; ++a)
                    corners[c](static_cast<int>(a)) = toNumber(f[base + 3 * c + a], path, line_no, base + 3 * c + a + 1);
            obs::Detection3D d;
            d.confidence = static_cast<float>(toNumber(f[base + 24], path, line_no, base + 25));
            const double cls = toNumber(f[base + 25], path, line_no, base + 26);
            if (cls < 0 || std::floor(cls) != cls || cls >= static_cast<double>(class_names.size()))
                failAt(path, line_no, "column " + std::to_string(base + 26) + ": unknown class " + trimBlanks(f[base + 25]) +
                                          " (expected an id 0.." + std::to_string(class_names.size() - 1) + ")");
            d.class_id = static_cast<std::uint16_t>(cls);
            try {
                d.box_in_camera = boxFromOmni3DCorners(corners);
                // The 8 corners must be a box (1 mm + 0.1 % of its diagonal): anything else is not a detection.
                const auto refit = omni3DCorners(d.box_in_camera);
                double off = 0;
                for (std::size_t c = 0; c < 8; ++c) off = std::max(off, (refit[c] - corners[c]).norm());
                if (!(off <= 1e-3 + 1e-3 * d.box_in_camera.size.norm()))
                    throw std::invalid_argument("the 8 corners do not form a box (a corner is " + std::to_string(off) +
                                                " m off the fitted box)");
                obs::validateDetection(d, class_names.size(), "object " + std::to_string(k));
            } catch (const std::exception& e) {
                failAt(path, line_no, std::string("object ") + std::to_string(k) + ": " + e.what());
            }
            im.detections.push_back(d);
        }
        set.images.push_back(im);
    }
    if (set.images.empty()) failAt(path, 0, "no detection rows (an empty file makes a rawlog without frames)");
    return set;
}

void writeRosDetectionsCsv(const std::string& path, const DetectionSet& set) {
    const std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    out << "# timestamp,camera,{v0x,v0y,v0z,...,v7z,confidence,class}*N  (camera frame, m; Omni3D corner order)\n";
    for (const DetectionImage& im : set.images) {
        out << im.timestamp_s << ',' << im.camera;
        for (const obs::Detection3D& d : im.detections) {
            for (const Eigen::Vector3d& c : omni3DCorners(d.box_in_camera)) out << ',' << c.x() << ',' << c.y() << ',' << c.z();
            out << ',' << static_cast<double>(d.confidence) << ',' << d.class_id;
        }
        out << '\n';
    }
    if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace simp::detector_io
