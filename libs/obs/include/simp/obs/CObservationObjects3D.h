#pragma once
/// \file CObservationObjects3D.h
/// The 3D object detections of one camera frame, as an MRPT observation.

#include <mrpt/img/TCamera.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/opengl/Visualizable.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/geometry/ConvexPolygon.h>
#include <simp/obs/Detection3D.h>

#include <optional>
#include <string>
#include <vector>

namespace simp::obs {

/** The 3D object detections of one camera frame (Cube R-CNN style output).
 *
 * Frames (doc/conventions.md):
 *  - robot: x forward, y left, z up (MRPT);
 *  - camera optical frame: x right, y down, z forward (the detector's);
 *  - `cameraPose()` is the pose of the camera optical frame in the robot frame.
 *
 * One observation per camera; a multi-camera rig gives one observation per camera in
 * the same mrpt::obs::CSensoryFrame. Detections are validated on every way in
 * (setters and deserialization): invalid ones are rejected with an exception that
 * names the detection index and the field.
 *
 * As an mrpt::opengl::Visualizable, RawLogViewer (MRPT >= 2.3) draws it in its 3D view.
 */
class CObservationObjects3D : public mrpt::obs::CObservation, public mrpt::opengl::Visualizable {
    DEFINE_SERIALIZABLE(CObservationObjects3D, simp::obs)

   public:
    CObservationObjects3D();

    /// @name Camera
    /// @{
    const mrpt::poses::CPose3D& cameraPose() const { return m_camera_pose; }
    void setCameraPose(const mrpt::poses::CPose3D& robot_T_camera);
    const std::optional<mrpt::img::TCamera>& intrinsics() const { return m_intrinsics; }
    void setIntrinsics(const std::optional<mrpt::img::TCamera>& K) { m_intrinsics = K; }
    std::uint32_t imageWidth() const { return m_image_width; }
    std::uint32_t imageHeight() const { return m_image_height; }
    void setImageSize(std::uint32_t width_px, std::uint32_t height_px);
    /// @}

    /// @name Detections
    /// @{
    const std::vector<std::string>& classNames() const { return m_class_names; }
    /// Replaces the label set; throws if a current detection's class id falls outside it.
    void setClassNames(const std::vector<std::string>& names);
    const std::string& classNameOf(const Detection3D& d) const { return m_class_names.at(d.class_id); }

    const std::vector<Detection3D>& detections() const { return m_detections; }
    /// Validates then appends; throws std::invalid_argument naming the field.
    void addDetection(const Detection3D& d);
    /// Validates all then replaces; on error nothing changes.
    void setDetections(const std::vector<Detection3D>& dets);
    std::size_t size() const { return m_detections.size(); }
    bool empty() const { return m_detections.empty(); }
    /// @}

    /// @name Geometry helpers
    /// @{
    /// Box of detection i in the robot frame (cached; recomputed by the setters).
    const geometry::Box3D& boxInRobot(std::size_t i) const { return m_boxes_in_robot.at(i); }
    /// Ground footprint of detection i in the robot frame (cached).
    const geometry::ConvexPolygon& footprintInRobot(std::size_t i) const { return m_footprints_in_robot.at(i); }
    /// Box of detection i in the world for the robot at `world_T_robot`.
    geometry::Box3D boxInWorld(std::size_t i, const mrpt::poses::CPose3D& world_T_robot) const;
    /// The 8 corners (numbering of geometry::Box3D) in camera, robot and world frames.
    std::array<Eigen::Vector3d, 8> cornersInCamera(std::size_t i) const;
    std::array<Eigen::Vector3d, 8> cornersInRobot(std::size_t i) const;
    std::array<Eigen::Vector3d, 8> cornersInWorld(std::size_t i, const mrpt::poses::CPose3D& world_T_robot) const;
    /// Convex ground footprint of detection i in the world frame.
    geometry::ConvexPolygon footprintInWorld(std::size_t i, const mrpt::poses::CPose3D& world_T_robot) const;
    /// @}

    /// @name mrpt::obs::CObservation interface
    /// @{
    void getSensorPose(mrpt::poses::CPose3D& out) const override { out = m_camera_pose; }
    void setSensorPose(const mrpt::poses::CPose3D& p) override { setCameraPose(p); }
    /// Camera pose, image size, intrinsics, then a table of the detections with the columns of
    /// detectionColumnNames() (doc/observation.md).
    void getDescriptionAsText(std::ostream& o) const override;
    /// One row per detection (an observation without detections: one row with detection -1),
    /// every row `8 + detectionColumnNames().size()` whitespace-separated columns: the time (written
    /// by rawlog-edit), the camera pose, num_detections, then the detection's columns.
    bool exportTxtSupported() const override { return true; }
    std::string exportTxtHeader() const override;
    std::string exportTxtDataRow() const override;
    /// @}

    /// @name mrpt::opengl::Visualizable (RawLogViewer's 3D view)
    /// @{
    /// In the robot frame: the robot's XYZ axes, the camera's axes at cameraPose(), and per
    /// detection a wireframe box in its class colour (simp::obs::classColorRgb) with a label
    /// "<class> <confidence>".
    void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
    /// @}

    /// @name Text columns of a detection (getDescriptionAsText and --export-txt share them)
    /// @{
    /// detection class_id class_name confidence cx cy cz W H L qw qx qy qz x_min y_min x_max
    /// y_max detector_id. The box is in the camera frame (m); the 2D box (px) is nan and the
    /// detector id -1 when absent; the class name has its blanks replaced by '_'.
    static const std::vector<std::string>& detectionColumnNames();
    /// The values of those columns for detection i (i = -1: the placeholder row of an
    /// observation without detections: class "-", numbers nan).
    std::vector<std::string> detectionColumns(long i) const;
    /// @}

    /// The version serializeTo() writes; tests and tools may lower it to produce files
    /// for older readers (0 .. current). Process-wide, default = current.
    static void setWriteVersion(std::uint8_t version);
    static std::uint8_t currentVersion();

   private:
    void refreshCache();

    mrpt::poses::CPose3D m_camera_pose;
    std::optional<mrpt::img::TCamera> m_intrinsics;
    std::uint32_t m_image_width = 640, m_image_height = 480;
    std::vector<std::string> m_class_names;
    std::vector<Detection3D> m_detections;

    std::vector<geometry::Box3D> m_boxes_in_robot;
    std::vector<geometry::ConvexPolygon> m_footprints_in_robot;
};

/// Pose in the robot frame of a camera optical frame (x right, y down, z forward) whose
/// optical axis is horizontal, looking towards `yaw_rad` (0 = robot forward, pi/2 = left),
/// tilted down by `pitch_down_rad`, at (x, y, z) m.
mrpt::poses::CPose3D cameraPoseOnRobot(double x, double y, double z, double yaw_rad, double pitch_down_rad = 0.0);

}  // namespace simp::obs
