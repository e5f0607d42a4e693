/// \file CameraRig.cpp
#include <simp/world/JsonRead.h>

#include <simp/io/StrictIni.h>
#include <simp/io/StrictNumber.h>
#include <mrpt/system/string_utils.h>
#include <simp/obs/InputLimits.h>
#include <simp/detector_io/CameraRig.h>
#include <simp/obs/CObservationObjects3D.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <set>

namespace simp::detector_io {

mrpt::poses::CPose3D RigCamera::robotTCamera() const {
    return obs::cameraPoseOnRobot(x_m, y_m, z_m, yaw_rad, pitch_down_rad);
}

int CameraRig::indexOf(const std::string& name) const {
    for (std::size_t i = 0; i < cameras.size(); ++i)
        if (cameras[i].name == name) return static_cast<int>(i);
    return -1;
}

namespace {

/// Fills one camera from a key getter: get(key, required) -> value (NaN when absent, optional).
RigCamera cameraFrom(const std::string& name, const std::function<double(const std::string&, bool)>& get,
                     const std::string& file, const std::string& where) {
    RigCamera c;
    c.name = name;
    c.x_m = get("x", true);
    c.y_m = get("y", true);
    c.z_m = get("z", true);
    c.yaw_rad = get("yaw_rad", true);
    const double pitch = get("pitch_down_rad", false);
    c.pitch_down_rad = std::isnan(pitch) ? 0.0 : pitch;
    const double fx = get("fx", true), fy = get("fy", true), cx = get("cx", true), cy = get("cy", true);
    const double w = get("width", true), h = get("height", true);
    if (!(fx > 0) || !(fy > 0)) world::failAt(file, where + ".fx/fy", "focal lengths must be > 0 px");
    if (!(w >= 1) || !(h >= 1) || std::floor(w) != w || std::floor(h) != h)
        world::failAt(file, where + ".width/height", "expected positive integers (px)");
    if (w > obs::limits::kMaxImageSide_px || h > obs::limits::kMaxImageSide_px)
        world::failAt(file, where + ".width/height",
                      "image side exceeds the maximum " + std::to_string(obs::limits::kMaxImageSide_px) + " px");
    for (double v : {c.x_m, c.y_m, c.z_m})
        if (!(std::abs(v) <= 100.0)) world::failAt(file, where + ".x/y/z", "camera more than 100 m from the robot");
    c.intrinsics.ncols = static_cast<uint32_t>(w);
    c.intrinsics.nrows = static_cast<uint32_t>(h);
    c.intrinsics.setIntrinsicParamsFromValues(fx, fy, cx, cy);
    return c;
}

CameraRig loadIni(const std::string& path) {
    const io::StrictIni cfg(path);
    const std::string list = cfg.read_string("rig", "cameras", "");
    if (list.empty()) world::failAt(path, "[rig] cameras", "missing: list the camera section names");
    std::vector<std::string> names;
    mrpt::system::tokenize(list, " \t,", names);
    CameraRig rig;
    for (const std::string& name : names) {
        if (!cfg.sectionExists(name)) world::failAt(path, "[" + name + "]", "missing section for camera '" + name + "'");
        const auto get = [&](const std::string& key, bool required) {
            const std::string v = mrpt::system::trim(cfg.read_string(name, key, ""));
            if (v.empty()) {
                if (required) world::failAt(path, "[" + name + "] " + key, "missing key");
                return std::nan("");
            }
            const auto x = io::parseFiniteNumber(v);
            if (!x) world::failAt(path, "[" + name + "] " + key, "expected a finite number, got '" + v + "'");
            return *x;
        };
        rig.cameras.push_back(cameraFrom(name, get, path, "[" + name + "]"));
    }
    cfg.checkUnknown();
    return rig;
}

CameraRig loadJson(const std::string& path) {
    const nlohmann::json j = world::readJsonFile(path);
    const nlohmann::json& cams = world::requireKey(j, "cameras", path, "cameras");
    if (!cams.is_array()) world::failAt(path, "cameras", "expected a list of cameras");
    CameraRig rig;
    for (std::size_t i = 0; i < cams.size(); ++i) {
        const std::string where = "cameras[" + std::to_string(i) + "]";
        const std::string name = world::asString(world::requireKey(cams[i], "name", path, where + ".name"), path, where + ".name");
        const auto get = [&](const std::string& key, bool required) {
            if (!cams[i].contains(key)) {
                if (required) world::failAt(path, where + "." + key, "missing key");
                return std::nan("");
            }
            return world::asNumber(cams[i][key], path, where + "." + key);
        };
        rig.cameras.push_back(cameraFrom(name, get, path, where));
    }
    return rig;
}

}  // namespace

CameraRig loadCameraRig(const std::string& path) {
    if (!std::filesystem::exists(path)) world::failAt(path, "", "file not found");
    const std::string ext = std::filesystem::path(path).extension().string();
    CameraRig rig = ext == ".json" ? loadJson(path) : loadIni(path);
    if (rig.cameras.empty()) world::failAt(path, "cameras", "no camera defined");
    std::set<std::string> names;
    for (const auto& c : rig.cameras)
        if (!names.insert(c.name).second) world::failAt(path, c.name, "duplicate camera name");
    return rig;
}

}  // namespace simp::detector_io
