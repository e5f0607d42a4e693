// CObservationObjects3D: text for humans (getDescriptionAsText, RawLogViewer's text pane) and
// for tables (rawlog-edit --export-txt). Both print the same detection columns.
#include <simp/obs/CObservationObjects3D.h>

#include <mrpt/system/datetime.h>

#include <Eigen/Geometry>
#include <cctype>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace simp::obs {
namespace {

std::string number(double v, int precision) {
    std::ostringstream s;
    s << std::setprecision(precision) << v;
    return s.str();
}

/// A class name as one whitespace-free token ("potted plant" -> "potted_plant", "" -> "-").
std::string token(const std::string& name) {
    std::string t = name;
    for (char& c : t)
        if (std::isspace(static_cast<unsigned char>(c))) c = '_';
    return t.empty() ? "-" : t;
}

}  // namespace

const std::vector<std::string>& CObservationObjects3D::detectionColumnNames() {
    static const std::vector<std::string> kNames = {
        "detection", "class_id", "class_name", "confidence", "cx[m]",  "cy[m]",  "cz[m]",  "W[m]",      "H[m]", "L[m]",
        "qw",        "qx",       "qy",         "qz",         "x_min[px]", "y_min[px]", "x_max[px]", "y_max[px]", "detector_id"};
    return kNames;
}

std::vector<std::string> CObservationObjects3D::detectionColumns(long i) const {
    if (i < 0 || static_cast<std::size_t>(i) >= m_detections.size()) {
        std::vector<std::string> row(detectionColumnNames().size(), "nan");
        row[0] = "-1", row[1] = "-1", row[2] = "-", row.back() = "-1";
        return row;
    }
    const auto& d = m_detections[static_cast<std::size_t>(i)];
    const auto& b = d.box_in_camera;
    const Eigen::Quaterniond q(b.R);
    std::vector<std::string> row = {std::to_string(i), std::to_string(d.class_id), token(classNameOf(d)),
                                    number(d.confidence, 6)};
    for (double v : {b.center.x(), b.center.y(), b.center.z(), b.size.x(), b.size.y(), b.size.z()})
        row.push_back(number(v, 9));
    for (double v : {q.w(), q.x(), q.y(), q.z()}) row.push_back(number(v, 9));
    if (d.box_2d)
        for (float v : {d.box_2d->x_min, d.box_2d->y_min, d.box_2d->x_max, d.box_2d->y_max}) row.push_back(number(v, 7));
    else
        row.insert(row.end(), 4, "nan");
    row.push_back(d.detector_id ? std::to_string(*d.detector_id) : "-1");
    return row;
}

void CObservationObjects3D::getDescriptionAsText(std::ostream& o) const {
    CObservation::getDescriptionAsText(o);
    o << "Camera pose on robot (x,y,z [m], yaw,pitch,roll [deg]): " << m_camera_pose.asString() << "\n";
    o << "Image size: " << m_image_width << " x " << m_image_height << " px\n";
    if (m_intrinsics)
        o << "Intrinsics: fx=" << m_intrinsics->fx() << " fy=" << m_intrinsics->fy() << " cx=" << m_intrinsics->cx()
          << " cy=" << m_intrinsics->cy() << " px\n";
    else
        o << "Intrinsics: (not given)\n";
    o << "Detections: " << m_detections.size()
      << "  (box in the camera frame: x right, y down, z forward; 2D box nan and detector_id -1 when absent)\n";
    // Fixed-width columns: each at least as wide as its name, class names padded to the longest.
    const auto& names = detectionColumnNames();
    std::vector<std::size_t> width(names.size());
    for (std::size_t c = 0; c < names.size(); ++c) width[c] = std::max<std::size_t>(names[c].size(), 9);
    std::vector<std::vector<std::string>> rows;
    for (std::size_t i = 0; i < m_detections.size(); ++i) {
        rows.push_back(detectionColumns(static_cast<long>(i)));
        for (std::size_t c = 0; c < names.size(); ++c) width[c] = std::max(width[c], rows.back()[c].size());
    }
    if (rows.empty()) return;
    const auto printRow = [&](const std::vector<std::string>& row) {
        for (std::size_t c = 0; c < row.size(); ++c) o << (c ? " " : "") << std::setw(static_cast<int>(width[c])) << row[c];
        o << "\n";
    };
    printRow(names);
    for (const auto& row : rows) printRow(row);
}

std::string CObservationObjects3D::exportTxtHeader() const {
    std::string h = "cam_x[m] cam_y[m] cam_z[m] cam_yaw[rad] cam_pitch[rad] cam_roll[rad] num_detections";
    for (const auto& n : detectionColumnNames()) h += " " + n;
    return h;
}

std::string CObservationObjects3D::exportTxtDataRow() const {
    // rawlog-edit prints "%16.6f " (the time) before the returned text and a newline after it:
    // the rows after the first carry the same time in the same format, so every row has all columns.
    std::string camera;
    for (double v : {m_camera_pose.x(), m_camera_pose.y(), m_camera_pose.z(), m_camera_pose.yaw(), m_camera_pose.pitch(),
                     m_camera_pose.roll()})
        camera += number(v, 9) + " ";
    camera += std::to_string(m_detections.size());
    char time[64];
    std::snprintf(time, sizeof(time), "%16.6f ", mrpt::Clock::toDouble(timestamp));

    std::vector<long> rows;  // detection indices; -1: the placeholder of an empty observation
    for (std::size_t i = 0; i < m_detections.size(); ++i) rows.push_back(static_cast<long>(i));
    if (rows.empty()) rows.push_back(-1);
    std::string out;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (k > 0) out += "\n" + std::string(time);
        out += camera;
        for (const auto& v : detectionColumns(rows[k])) out += " " + v;
    }
    return out;
}

}  // namespace simp::obs
