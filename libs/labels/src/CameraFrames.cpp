/// \file CameraFrames.cpp
#include <simp/world/JsonRead.h>

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/obs/InputLimits.h>
#include <simp/labels/CameraFrames.h>

#include <cmath>

#include <set>

namespace simp::labels {

namespace {

/// Fills K, size and pose of `im` from the rig camera and the interpolated robot pose.
void poseFromRig(PosedImage& im, const nlohmann::json& o, const detector_io::CameraRig* rig,
                 const std::vector<io::StampedPose2D>* poses, const std::string& path, const std::string& k) {
    const std::string cam = world::asString(o["camera"], path, k + ".camera");
    if (!rig || !poses)
        world::failAt(path, k + ".camera", "an image given by camera name needs --rig and --poses");
    const int c = rig->indexOf(cam);
    if (c < 0) world::failAt(path, k + ".camera", "camera '" + cam + "' is not in the rig file");
    if (!o.contains("timestamp")) world::failAt(path, k + ".timestamp", "missing key (needed with \"camera\")");
    mrpt::math::TPose2D p;
    if (!io::interpolatePose(*poses, im.timestamp_s, p))
        world::failAt(path, k + ".timestamp", "time " + std::to_string(im.timestamp_s) + " s is outside the poses' range");
    const detector_io::RigCamera& rc = rig->cameras[static_cast<std::size_t>(c)];
    im.camera = camera::PinholeCamera::onRobot(mrpt::poses::CPose3D(mrpt::poses::CPose2D(p)), rc.robotTCamera(), rc.intrinsics);
}

}  // namespace

std::vector<PosedImage> readCameraFrames(const std::string& path, const detector_io::CameraRig* rig,
                                         const std::vector<io::StampedPose2D>* poses) {
    const nlohmann::json j = world::readJsonFile(path);
    const nlohmann::json& ims = world::requireKey(j, "images", path, "images");
    if (!ims.is_array()) world::failAt(path, "images", "expected a list of images");
    std::vector<PosedImage> out;
    std::set<std::int64_t> ids;
    for (std::size_t i = 0; i < ims.size(); ++i) {
        const std::string k = "images[" + std::to_string(i) + "]";
        const nlohmann::json& o = ims[i];
        PosedImage im;
        im.id = world::asInteger(world::requireKey(o, "id", path, k + ".id"), path, k + ".id");
        if (!ids.insert(im.id).second) world::failAt(path, k + ".id", "duplicate image id " + std::to_string(im.id));
        im.file_path = world::asString(world::requireKey(o, "file_path", path, k + ".file_path"), path, k + ".file_path");
        if (o.contains("timestamp")) im.timestamp_s = world::asNumber(o["timestamp"], path, k + ".timestamp");
        if (o.contains("camera")) {
            poseFromRig(im, o, rig, poses, path, k);
            out.push_back(im);
            continue;
        }
        const long long w = world::asInteger(world::requireKey(o, "width", path, k + ".width"), path, k + ".width");
        const long long h = world::asInteger(world::requireKey(o, "height", path, k + ".height"), path, k + ".height");
        if (w <= 0 || h <= 0) world::failAt(path, k + ".width/height", "must be > 0 px");
        // Labels work per pixel: a 2e9 x 2e9 px image once ran for minutes (doc/formats.md limits).
        if (w > obs::limits::kMaxImageSide_px || h > obs::limits::kMaxImageSide_px)
            world::failAt(path, k + ".width/height",
                          std::to_string(w) + " x " + std::to_string(h) + " px exceeds the maximum side " +
                              std::to_string(obs::limits::kMaxImageSide_px) + " px");
        const Eigen::Matrix3d K = world::asMatrix3(world::requireKey(o, "K", path, k + ".K"), path, k + ".K");
        if (!(K(0, 0) > 0) || !(K(1, 1) > 0) || K(1, 0) != 0 || K(2, 0) != 0 || K(2, 1) != 0 || K(2, 2) != 1)
            world::failAt(path, k + ".K", "expected [[fx, s, cx], [0, fy, cy], [0, 0, 1]] with fx, fy > 0");
        im.camera.setIntrinsics(K, static_cast<int>(w), static_cast<int>(h));
        const auto p = world::asNumberArray(world::requireKey(o, "position_m", path, k + ".position_m"), 3, path, k + ".position_m");
        for (double x : p)
            if (!(std::abs(x) <= obs::limits::kMaxCoordinate_m))
                world::failAt(path, k + ".position_m", "coordinate beyond " + std::to_string(obs::limits::kMaxCoordinate_m) + " m");
        Eigen::Matrix3d R;
        if (o.contains("quaternion_wxyz")) {
            const auto q = world::asNumberArray(o["quaternion_wxyz"], 4, path, k + ".quaternion_wxyz");
            const Eigen::Quaterniond quat(q[0], q[1], q[2], q[3]);
            if (std::abs(quat.norm() - 1.0) > 1e-6) world::failAt(path, k + ".quaternion_wxyz", "not a unit quaternion");
            R = quat.normalized().toRotationMatrix();
        } else {
            R = world::asMatrix3(world::requireKey(o, "rotation", path, k + ".rotation"), path, k + ".rotation");
            if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-6 || R.determinant() < 0)
                world::failAt(path, k + ".rotation", "not a rotation matrix (R^T R = I, det R = +1, tol 1e-6)");
        }
        im.camera.world_T_camera.linear() = R;
        im.camera.world_T_camera.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
        out.push_back(im);
    }
    return out;
}

void writeCameraFrames(const std::string& path, const std::vector<PosedImage>& images) {
    nlohmann::ordered_json ims = nlohmann::ordered_json::array();
    for (const PosedImage& im : images) {
        nlohmann::ordered_json o;
        o["id"] = im.id;
        o["file_path"] = im.file_path;
        o["timestamp"] = im.timestamp_s;
        o["width"] = im.camera.widthPx();
        o["height"] = im.camera.heightPx();
        o["K"] = world::toJson(im.camera.K());
        o["position_m"] = world::toJson(Eigen::Vector3d(im.camera.world_T_camera.translation()));
        o["rotation"] = world::toJson(Eigen::Matrix3d(im.camera.world_T_camera.linear()));
        ims.push_back(o);
    }
    world::writeJsonFile(nlohmann::ordered_json{{"images", ims}}, path, world::JsonLayout::Indent1);
}

}  // namespace simp::labels
