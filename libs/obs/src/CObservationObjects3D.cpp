#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/stl_serialization.h>
#include <mrpt/system/datetime.h>
#include <simp/geometry/Footprint.h>
#include <simp/obs/ArchiveRead.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/InputLimits.h>
#include <simp/obs/ObjectClasses.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <atomic>
#include <iomanip>
#include <sstream>
#include <stdexcept>

IMPLEMENTS_SERIALIZABLE(CObservationObjects3D, CObservation, simp::obs)

namespace simp::obs {
namespace {

// Version history (doc/observation.md):
//  0: timestamp, label, camera pose, class names, detections (class, confidence, centre, size, quaternion)
//  1: + image size, optional intrinsics, per detection optional 2D box and detector id
constexpr std::uint8_t kCurrentVersion = 1;
std::atomic<std::uint8_t> g_write_version{kCurrentVersion};

Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& p) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = p.getRotationMatrix().asEigen();
    T.translation() = Eigen::Vector3d(p.x(), p.y(), p.z());
    return T;
}

std::string detectionWhere(std::size_t i) { return "detection #" + std::to_string(i); }

/// A camera pose read from a file: finite and within limits::kMaxCoordinate_m of the robot.
void validateCameraPose(const mrpt::poses::CPose3D& p) {
    const auto R = p.getRotationMatrix().asEigen();
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()) || !R.allFinite())
        throw std::invalid_argument("observation: field 'camera_pose' is not finite");
    const double m = std::max({std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
    if (m > limits::kMaxCoordinate_m)
        throw std::invalid_argument("observation: field 'camera_pose' translation " + std::to_string(m) +
                                    " m exceeds the maximum " + std::to_string(limits::kMaxCoordinate_m) + " m");
}

}  // namespace

CObservationObjects3D::CObservationObjects3D() : m_class_names(defaultClassNames()) {}

void CObservationObjects3D::setWriteVersion(std::uint8_t version) {
    if (version > kCurrentVersion) throw std::invalid_argument("CObservationObjects3D: unknown write version");
    g_write_version = version;
}
std::uint8_t CObservationObjects3D::currentVersion() { return kCurrentVersion; }

void CObservationObjects3D::setCameraPose(const mrpt::poses::CPose3D& robot_T_camera) {
    m_camera_pose = robot_T_camera;
    refreshCache();
}

void CObservationObjects3D::setImageSize(std::uint32_t width_px, std::uint32_t height_px) {
    m_image_width = width_px;
    m_image_height = height_px;
}

void CObservationObjects3D::setClassNames(const std::vector<std::string>& names) {
    for (std::size_t i = 0; i < m_detections.size(); ++i)
        if (m_detections[i].class_id >= names.size())
            throw std::invalid_argument(detectionWhere(i) + ": field 'class_id' = " +
                                        std::to_string(m_detections[i].class_id) +
                                        " is out of range of the new class list");
    m_class_names = names;
}

void CObservationObjects3D::addDetection(const Detection3D& d) {
    validateDetection(d, m_class_names.size(), detectionWhere(m_detections.size()));
    m_detections.push_back(d);
    refreshCache();
}

void CObservationObjects3D::setDetections(const std::vector<Detection3D>& dets) {
    for (std::size_t i = 0; i < dets.size(); ++i) validateDetection(dets[i], m_class_names.size(), detectionWhere(i));
    m_detections = dets;
    refreshCache();
}

void CObservationObjects3D::refreshCache() {
    const Eigen::Isometry3d robot_T_camera = toIsometry(m_camera_pose);
    m_boxes_in_robot.clear();
    m_footprints_in_robot.clear();
    m_boxes_in_robot.reserve(m_detections.size());
    m_footprints_in_robot.reserve(m_detections.size());
    for (const auto& d : m_detections) {
        m_boxes_in_robot.push_back(d.box_in_camera.transformed(robot_T_camera));
        m_footprints_in_robot.push_back(geometry::footprint(m_boxes_in_robot.back()));
    }
}

geometry::Box3D CObservationObjects3D::boxInWorld(std::size_t i, const mrpt::poses::CPose3D& world_T_robot) const {
    return boxInRobot(i).transformed(toIsometry(world_T_robot));
}

std::array<Eigen::Vector3d, 8> CObservationObjects3D::cornersInCamera(std::size_t i) const {
    return m_detections.at(i).box_in_camera.corners();
}
std::array<Eigen::Vector3d, 8> CObservationObjects3D::cornersInRobot(std::size_t i) const {
    return boxInRobot(i).corners();
}
std::array<Eigen::Vector3d, 8> CObservationObjects3D::cornersInWorld(std::size_t i,
                                                                    const mrpt::poses::CPose3D& world_T_robot) const {
    return boxInWorld(i, world_T_robot).corners();
}
geometry::ConvexPolygon CObservationObjects3D::footprintInWorld(std::size_t i,
                                                               const mrpt::poses::CPose3D& world_T_robot) const {
    return geometry::footprint(boxInWorld(i, world_T_robot));
}

// ---------------------------------------------------------------- serialization
uint8_t CObservationObjects3D::serializeGetVersion() const { return g_write_version; }

void CObservationObjects3D::serializeTo(mrpt::serialization::CArchive& out) const {
    const std::uint8_t version = g_write_version;
    out << timestamp << sensorLabel << m_camera_pose << m_class_names;
    if (version >= 1) {
        out << m_image_width << m_image_height << m_intrinsics.has_value();
        if (m_intrinsics) out << *m_intrinsics;
    }
    out.WriteAs<uint32_t>(m_detections.size());
    for (const auto& d : m_detections) {
        const Eigen::Quaterniond q(d.box_in_camera.R);
        out << d.class_id << d.confidence;
        out << d.box_in_camera.center.x() << d.box_in_camera.center.y() << d.box_in_camera.center.z();
        out << d.box_in_camera.size.x() << d.box_in_camera.size.y() << d.box_in_camera.size.z();
        out << q.w() << q.x() << q.y() << q.z();
        if (version >= 1) {
            out << d.box_2d.has_value();
            if (d.box_2d) out << d.box_2d->x_min << d.box_2d->y_min << d.box_2d->x_max << d.box_2d->y_max;
            out << d.detector_id.has_value();
            if (d.detector_id) out << *d.detector_id;
        }
    }
}

void CObservationObjects3D::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    // The archive is untrusted (rawlogs travel between labs): counts and lengths are checked
    // against doc/formats.md's limits and the bytes left before anything is allocated
    // (ArchiveRead.h), bool bytes must be 0 or 1, numbers are validated per field.
    switch (version) {
        case 0:
        case 1: {
            namespace ar = archive;
            in >> timestamp;
            sensorLabel = ar::readString(in, limits::kMaxNameLength, "observation: field 'sensorLabel'");
            in >> m_camera_pose;
            validateCameraPose(m_camera_pose);
            m_class_names = ar::readStringList(in, limits::kMaxClasses, limits::kMaxNameLength,
                                               "observation: field 'class_names'");
            m_intrinsics.reset();
            m_image_width = 640;
            m_image_height = 480;
            if (version >= 1) {
                in >> m_image_width >> m_image_height;
                if (m_image_width > limits::kMaxImageSide_px || m_image_height > limits::kMaxImageSide_px)
                    throw std::invalid_argument("observation: field 'image size' = " + std::to_string(m_image_width) +
                                                " x " + std::to_string(m_image_height) + " px exceeds the maximum side " +
                                                std::to_string(limits::kMaxImageSide_px) + " px");
                if (ar::readBool(in, "observation: field 'has_intrinsics'"))
                    m_intrinsics = ar::readCamera(in, "observation: field 'intrinsics'");
            }
            // Smallest detection on the wire: class (2) + confidence (4) + 10 doubles, + 2 flags in v1.
            const std::size_t min_bytes = 2 + 4 + 10 * 8 + (version >= 1 ? 2 : 0);
            const auto n = ar::readCount(in, min_bytes, limits::kMaxDetectionsPerFrame, "observation: detection count");
            std::vector<Detection3D> dets;
            dets.reserve(n);
            for (std::size_t i = 0; i < n; ++i) {
                Detection3D d;
                double cx, cy, cz, w, h, l, qw, qx, qy, qz;
                in >> d.class_id >> d.confidence >> cx >> cy >> cz >> w >> h >> l >> qw >> qx >> qy >> qz;
                d.box_in_camera.center = {cx, cy, cz};
                d.box_in_camera.size = {w, h, l};
                const Eigen::Quaterniond q(qw, qx, qy, qz);
                const double norm = q.norm();
                if (!std::isfinite(norm) || std::abs(norm - 1.0) > 1e-3)
                    throw std::invalid_argument(detectionWhere(i) +
                                                ": field 'rotation' is not a unit quaternion in the archive");
                d.box_in_camera.R = q.normalized().toRotationMatrix();
                if (version >= 1) {
                    if (ar::readBool(in, detectionWhere(i) + ": field 'has_box_2d'")) {
                        ImageBox2D r;
                        in >> r.x_min >> r.y_min >> r.x_max >> r.y_max;
                        d.box_2d = r;
                    }
                    if (ar::readBool(in, detectionWhere(i) + ": field 'has_detector_id'")) {
                        std::int64_t id;
                        in >> id;
                        d.detector_id = id;
                    }
                }
                validateDetection(d, m_class_names.size(), detectionWhere(i));
                dets.push_back(d);
            }
            m_detections = std::move(dets);
            refreshCache();
        } break;
        default:
            MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    }
}

// ---------------------------------------------------------------- text
mrpt::poses::CPose3D cameraPoseOnRobot(double x, double y, double z, double yaw_rad, double pitch_down_rad) {
    // Optical frame (x right, y down, z forward) relative to a robot-aligned frame looking forward:
    // columns are the optical axes in robot coordinates.
    Eigen::Matrix3d robot_R_optical;
    robot_R_optical << 0, 0, 1,  //
        -1, 0, 0,                //
        0, -1, 0;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                              Eigen::AngleAxisd(pitch_down_rad, Eigen::Vector3d::UnitY()).toRotationMatrix() *
                              robot_R_optical;
    mrpt::math::CMatrixDouble33 rot;
    rot.asEigen() = R;
    mrpt::math::CVectorFixedDouble<3> t;
    t[0] = x;
    t[1] = y;
    t[2] = z;
    return mrpt::poses::CPose3D(rot, t);
}

}  // namespace simp::obs
