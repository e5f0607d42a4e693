#include <mrpt/config/CConfigFileBase.h>
#include <simp/io/NameValueList.h>
#include <simp/io/StrictNumber.h>
#include <simp/mapping/MappingOptions.h>

#include <cmath>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace simp::mapping {
namespace {

using io::trimIniValue;

void requireFinite(double v, const char* name) {
    if (!std::isfinite(v)) throw std::invalid_argument(std::string("mapping option '") + name + "' is not a finite number");
}

void requireRange(double v, double lo, double hi, const char* name) {
    requireFinite(v, name);
    if (v < lo || v > hi) {
        std::ostringstream s;
        s << "mapping option '" << name << "' = " << v << " outside [" << lo << ", " << hi << "]";
        throw std::invalid_argument(s.str());
    }
}

/// Reads a double key; absent keeps `value`; anything but a whole finite number throws naming the key.
void readDouble(const mrpt::config::CConfigFileBase& c, const std::string& section, const char* key, double& value) {
    const std::string text = trimIniValue(c.read_string(section, key, "", false));
    if (text.empty()) return;
    const auto v = io::parseFiniteNumber(text);
    if (!v) throw std::invalid_argument("mapping option [" + section + "] " + key + " = '" + text + "' is not a finite number");
    value = *v;
}

void readInt(const mrpt::config::CConfigFileBase& c, const std::string& section, const char* key, int& value) {
    const std::string text = trimIniValue(c.read_string(section, key, "", false));
    if (text.empty()) return;
    value = static_cast<int>(io::parseInteger(text, "mapping option [" + section + "] " + key, -1000000, 1000000));
}

void readBool(const mrpt::config::CConfigFileBase& c, const std::string& section, const char* key, bool& value) {
    const std::string text = trimIniValue(c.read_string(section, key, "", false));
    if (!text.empty()) value = io::parseBool(text, "mapping option [" + section + "] " + key);
}

// The authors' mapping_args.json (categories, omni_conf, min_dist, max_dist).
struct AuthorsRow {
    const char* name;
    double conf, min_dist, max_dist;
};
constexpr AuthorsRow kAuthorsFilters[] = {
    {"sink", 0.7, 0.5, 3.0},     {"door", 0.0, 0.0, 0.0},         {"oven", 0.8, 0.0, 4.0},
    {"board", 0.9, 1.5, 4.5},    {"table", 0.7, 1.0, 4.5},        {"box", 0.0, 0.0, 0.0},
    {"potted plant", 0.95, 0.0, 4.5}, {"drawers", 0.8, 0.0, 3.5}, {"sofa", 0.7, 0.5, 3.0},
    {"cabinet", 0.9, 1.0, 5.0},  {"chair", 0.0, 0.0, 0.0},        {"fire extinguisher", 0.9, 0.0, 3.0},
    {"person", 0.0, 0.0, 0.0},   {"desk", 0.8, 0.5, 4.0},
};

}  // namespace

std::map<std::string, double> parseClassValueList(const std::string& text, const std::string& key) {
    std::map<std::string, double> out;
    for (const auto& [name, value] : io::parseNameValueList(text, "mapping option '" + key + "'")) out[name] = value;
    return out;
}

MappingOptions::MappingOptions() {
    for (const auto& r : kAuthorsFilters) per_class[r.name] = ClassFilter{r.conf, r.min_dist, r.max_dist};
}

const ClassFilter& MappingOptions::filterOf(const std::string& class_name) const {
    const auto it = per_class.find(class_name);
    return it == per_class.end() ? default_filter : it->second;
}

double MappingOptions::duplicateCenterRadiusOf(const std::string& class_name) const {
    const auto it = class_duplicate_center_radius_m.find(class_name);
    return it == class_duplicate_center_radius_m.end() ? duplicate_center_radius_m : it->second;
}

std::optional<WallAlignmentParams> MappingOptions::wallAlignmentOf(const std::string& class_name) const {
    const auto it = class_wall_align_max_gap_m.find(class_name);
    if (wall_align == WallAlignMode::Off || it == class_wall_align_max_gap_m.end()) return std::nullopt;
    WallAlignmentParams p;
    p.max_gap_m = it->second;
    p.max_penetration_m = wall_align_max_penetration_m;
    p.max_yaw_rad = wall_align_max_yaw_rad;
    p.max_residual_m = wall_align_max_residual_m;
    p.rays_per_side = wall_align_rays;
    return p;
}

void MappingOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) {
    // Unknown keys: io::StrictIni::checkUnknown() after loading (the keys read here are the known ones).
    readDouble(c, s, "trigger_dist_m", trigger_dist_m);
    readDouble(c, s, "trigger_angle_rad", trigger_angle_rad);
    readDouble(c, s, "tau_cost", tau_cost);
    readDouble(c, s, "tau_purge", tau_purge);
    readInt(c, s, "min_local_detections", min_local_detections);
    readDouble(c, s, "min_local_support", min_local_support);
    readInt(c, s, "min_confirmed_matches", min_confirmed_matches);
    readInt(c, s, "min_confirmed_windows", min_confirmed_windows);
    readBool(c, s, "merge_duplicates", merge_duplicates);
    readDouble(c, s, "duplicate_tau_cost", duplicate_tau_cost);
    readDouble(c, s, "duplicate_max_distance_m", duplicate_max_distance_m);
    readDouble(c, s, "duplicate_center_radius_m", duplicate_center_radius_m);
    readDouble(c, s, "duplicate_min_overlap", duplicate_min_overlap);
    readBool(c, s, "remove_class_bias", remove_class_bias);
    readBool(c, s, "hide_objects_in_walls", hide_objects_in_walls);
    {
        const std::string key = "class_duplicate_center_radius_m";
        const std::string text = c.read_string(s, key, "", false);
        if (!trimIniValue(text).empty()) class_duplicate_center_radius_m = parseClassValueList(text, key);
    }
    {
        const std::string mode = trimIniValue(c.read_string(s, "wall_align", "", false));
        if (mode == "auto") wall_align = WallAlignMode::Auto;
        else if (mode == "true" || mode == "on" || mode == "1") wall_align = WallAlignMode::On;
        else if (mode == "false" || mode == "off" || mode == "0") wall_align = WallAlignMode::Off;
        else if (!mode.empty())
            throw std::invalid_argument("mapping option [" + s + "] wall_align = '" + mode + "': expected auto, true or false");
    }
    readDouble(c, s, "wall_align_max_enclosed_unknown_m2", wall_align_max_enclosed_unknown_m2);
    {
        // An explicit (even empty) list replaces the default: "class_wall_align_max_gap_m = " aligns no class.
        const std::string key = "class_wall_align_max_gap_m";
        const std::string raw = c.read_string(s, key, "<absent>", false);
        if (raw != "<absent>") {
            const std::string text = trimIniValue(raw);
            class_wall_align_max_gap_m = text.empty() ? std::map<std::string, double>{} : parseClassValueList(text, key);
        }
    }
    readDouble(c, s, "wall_align_max_penetration_m", wall_align_max_penetration_m);
    readDouble(c, s, "wall_align_max_yaw_rad", wall_align_max_yaw_rad);
    readDouble(c, s, "wall_align_max_residual_m", wall_align_max_residual_m);
    readInt(c, s, "wall_align_rays", wall_align_rays);
    readBool(c, s, "intersecting_boxes_occlude", intersecting_boxes_occlude);
    readDouble(c, s, "cost_covariance_scale", cost_covariance_scale);
    readBool(c, s, "cost_uses_noise_mean", cost_uses_noise_mean);
    readDouble(c, s, "default_noise_sigma_m", default_noise_sigma_m);
    readDouble(c, s, "truncation_threshold", truncation_threshold);
    readDouble(c, s, "max_occluded_fraction", max_occluded_fraction);
    readInt(c, s, "zbuffer_downscale", zbuffer_downscale);
    readDouble(c, s, "wall_depth_margin_m", wall_depth_margin_m);
    readDouble(c, s, "wall_cast_max_m", wall_cast_max_m);
    readDouble(c, s, "near_plane_m", near_plane_m);
    readDouble(c, s, "default_fx_px", default_fx_px);
    readDouble(c, s, "default_fy_px", default_fy_px);
    readDouble(c, s, "default_cx_px", default_cx_px);
    readDouble(c, s, "default_cy_px", default_cy_px);
    readDouble(c, s, "default_min_confidence", default_filter.min_confidence);
    readDouble(c, s, "default_min_range_m", default_filter.min_range_m);
    readDouble(c, s, "default_max_range_m", default_filter.max_range_m);
    readInt(c, s, "update_min_missed_windows", update_min_missed_windows);
    readDouble(c, s, "update_max_seen_fraction", update_max_seen_fraction);
    readDouble(c, s, "update_move_max_distance_m", update_move_max_distance_m);
    readDouble(c, s, "update_min_move_m", update_min_move_m);
    readInt(c, s, "update_min_new_windows", update_min_new_windows);
    readDouble(c, s, "update_removal_alpha", update_removal_alpha);
    readDouble(c, s, "update_reassociate_max_seen_fraction", update_reassociate_max_seen_fraction);
    readDouble(c, s, "room_door_width_m", room_door_width_m);
    readDouble(c, s, "room_min_area_m2", room_min_area_m2);
    readDouble(c, s, "room_search_radius_m", room_search_radius_m);

    const std::string policy = trimIniValue(c.read_string(s, "room_update_policy", "", false));
    if (policy == "current_room") room_policy = RoomUpdatePolicy::CurrentRoom;
    else if (policy == "all") room_policy = RoomUpdatePolicy::All;
    else if (!policy.empty())
        throw std::invalid_argument("mapping option [" + s + "] room_update_policy = '" + policy + "': expected current_room or all");

    const std::pair<const char*, double ClassFilter::*> lists[] = {
        {"class_min_confidence", &ClassFilter::min_confidence},
        {"class_min_range_m", &ClassFilter::min_range_m},
        {"class_max_range_m", &ClassFilter::max_range_m}};
    for (const auto& [key, member] : lists) {
        const std::string text = c.read_string(s, key, "", false);
        if (trimIniValue(text).empty()) continue;
        for (const auto& [name, v] : parseClassValueList(text, key)) {
            auto it = per_class.find(name);
            if (it == per_class.end()) it = per_class.emplace(name, default_filter).first;
            it->second.*member = v;
        }
    }
    validate();
}

void MappingOptions::validate() const {
    requireRange(trigger_dist_m, 0.0, 1e3, "trigger_dist_m");
    requireRange(trigger_angle_rad, 0.0, 10.0, "trigger_angle_rad");
    requireRange(tau_cost, 0.0, 1.0, "tau_cost");
    requireRange(tau_purge, 0.0, 1e6, "tau_purge");
    requireRange(min_local_detections, 1, 1e6, "min_local_detections");
    requireRange(min_local_support, 0.0, 1e3, "min_local_support");
    requireRange(min_confirmed_matches, 1, 1e6, "min_confirmed_matches");
    requireRange(min_confirmed_windows, 1, 1e6, "min_confirmed_windows");
    requireRange(duplicate_tau_cost, 0.0, 1.0, "duplicate_tau_cost");
    requireRange(duplicate_max_distance_m, 0.0, 1e3, "duplicate_max_distance_m");
    requireRange(duplicate_center_radius_m, 0.0, 1e3, "duplicate_center_radius_m");
    requireRange(duplicate_min_overlap, 0.0, 1.0, "duplicate_min_overlap");
    for (const auto& [name, r] : class_duplicate_center_radius_m)
        requireRange(r, 0.0, 1e3, ("class_duplicate_center_radius_m of class '" + name + "'").c_str());
    for (const auto& [name, g] : class_wall_align_max_gap_m)
        requireRange(g, 0.0, 10.0, ("class_wall_align_max_gap_m of class '" + name + "'").c_str());
    requireRange(wall_align_max_penetration_m, 0.0, 10.0, "wall_align_max_penetration_m");
    requireRange(wall_align_max_enclosed_unknown_m2, 0.0, 1e9, "wall_align_max_enclosed_unknown_m2");
    requireRange(wall_align_max_yaw_rad, 0.0, 1.5, "wall_align_max_yaw_rad");
    requireRange(wall_align_max_residual_m, 0.0, 10.0, "wall_align_max_residual_m");
    requireRange(wall_align_rays, 2, 100, "wall_align_rays");
    requireRange(default_noise_sigma_m, 1e-6, 1e3, "default_noise_sigma_m");
    requireRange(cost_covariance_scale, 1e-6, 1e6, "cost_covariance_scale");
    requireRange(truncation_threshold, 0.0, 1.0, "truncation_threshold");
    requireRange(max_occluded_fraction, 0.0, 1.0, "max_occluded_fraction");
    requireRange(zbuffer_downscale, 1, 64, "zbuffer_downscale");
    requireRange(wall_depth_margin_m, 0.0, 1e3, "wall_depth_margin_m");
    requireRange(wall_cast_max_m, 0.0, 1e4, "wall_cast_max_m");
    requireRange(near_plane_m, 1e-4, 10.0, "near_plane_m");
    requireRange(default_fx_px, 1e-3, 1e6, "default_fx_px");
    requireRange(default_fy_px, 1e-3, 1e6, "default_fy_px");
    requireFinite(default_cx_px, "default_cx_px");
    requireFinite(default_cy_px, "default_cy_px");
    requireRange(update_min_missed_windows, 1, 1e6, "update_min_missed_windows");
    requireRange(update_max_seen_fraction, 0.0, 1.0, "update_max_seen_fraction");
    requireRange(update_move_max_distance_m, 0.0, 100.0, "update_move_max_distance_m");
    requireRange(update_min_move_m, 0.0, 100.0, "update_min_move_m");
    requireRange(update_min_new_windows, 1, 1e6, "update_min_new_windows");
    requireRange(update_removal_alpha, 0.0, 1.0, "update_removal_alpha");
    requireRange(update_reassociate_max_seen_fraction, 0.0, 1.0, "update_reassociate_max_seen_fraction");
    if (update_min_move_m > update_move_max_distance_m)
        throw std::invalid_argument("mapping option update_min_move_m (" + std::to_string(update_min_move_m) +
                                    ") must not exceed update_move_max_distance_m (" +
                                    std::to_string(update_move_max_distance_m) + ")");
    requireRange(room_door_width_m, 0.0, 100.0, "room_door_width_m");
    requireRange(room_min_area_m2, 0.0, 1e6, "room_min_area_m2");
    requireRange(room_search_radius_m, 0.0, 100.0, "room_search_radius_m");
    auto checkFilter = [](const ClassFilter& f, const std::string& who) {
        const std::string p = who + ".";
        requireRange(f.min_confidence, 0.0, 1.0, (p + "min_confidence").c_str());
        requireRange(f.min_range_m, 0.0, 1e4, (p + "min_range_m").c_str());
        requireRange(f.max_range_m, 0.0, 1e4, (p + "max_range_m").c_str());
    };
    checkFilter(default_filter, "default");
    for (const auto& [name, f] : per_class) checkFilter(f, "class '" + name + "'");
}

void MappingOptions::dumpToTextStream(std::ostream& o) const {
    o << "\n----------- [simp::mapping::MappingOptions] ------------\n";
    o << "trigger_dist_m        = " << trigger_dist_m << " m\n";
    o << "trigger_angle_rad     = " << trigger_angle_rad << " rad\n";
    o << "tau_cost              = " << tau_cost << "\n";
    o << "tau_purge             = " << tau_purge << "\n";
    o << "min_local_detections  = " << min_local_detections << "\n";
    o << "min_local_support     = " << min_local_support << " detections per time step\n";
    o << "min_confirmed_matches = " << min_confirmed_matches << " detections\n";
    o << "min_confirmed_windows = " << min_confirmed_windows << " integration windows\n";
    o << "merge_duplicates      = " << (merge_duplicates ? "true" : "false") << "\n";
    o << "duplicate_tau_cost    = " << duplicate_tau_cost << "\n";
    o << "duplicate_max_distance_m = " << duplicate_max_distance_m << " m\n";
    o << "duplicate_min_overlap = " << duplicate_min_overlap << (duplicate_min_overlap > 0 ? "" : " (off)") << "\n";
    o << "duplicate_center_radius_m = " << duplicate_center_radius_m << " m";
    for (const auto& [name, r] : class_duplicate_center_radius_m) o << ", " << name << ": " << r << " m";
    o << "\n";
    o << "wall_align            = "
      << (wall_align == WallAlignMode::Auto ? "auto" : wall_align == WallAlignMode::On ? "true" : "false")
      << " (auto: off above " << wall_align_max_enclosed_unknown_m2 << " m^2 enclosed unknown), max gap per class:";
    for (const auto& [name, g] : class_wall_align_max_gap_m) o << " " << name << ": " << g << " m,";
    o << " penetration <= " << wall_align_max_penetration_m << " m, yaw <= " << wall_align_max_yaw_rad
      << " rad, residual <= " << wall_align_max_residual_m << " m, " << wall_align_rays << " rays per side\n";
    o << "cost_covariance_scale = " << cost_covariance_scale << "\n";
    o << "intersecting_boxes_occlude = " << (intersecting_boxes_occlude ? "true" : "false") << "\n";
    o << "cost_uses_noise_mean  = " << (cost_uses_noise_mean ? "true" : "false") << "\n";
    o << "remove_class_bias     = " << (remove_class_bias ? "true" : "false") << "\n";
    o << "hide_objects_in_walls = " << (hide_objects_in_walls ? "true" : "false") << "\n";
    o << "default_noise_sigma_m = " << default_noise_sigma_m << " m\n";
    o << "truncation_threshold  = " << truncation_threshold << "\n";
    o << "max_occluded_fraction = " << max_occluded_fraction << "\n";
    o << "zbuffer_downscale     = " << zbuffer_downscale << " px\n";
    o << "wall_depth_margin_m   = " << wall_depth_margin_m << " m\n";
    o << "wall_cast_max_m       = " << wall_cast_max_m << " m\n";
    o << "near_plane_m          = " << near_plane_m << " m\n";
    o << "default K (fx fy cx cy) = " << default_fx_px << " " << default_fy_px << " " << default_cx_px << " "
      << default_cy_px << " px\n";
    o << "update: removed after >= " << update_min_missed_windows << " missed windows with seen fraction < "
      << update_max_seen_fraction << "; moved within " << update_move_max_distance_m << " m, re-estimated below "
      << update_min_move_m << " m; new objects after " << update_min_new_windows << " windows; removal alpha "
      << update_removal_alpha << "; re-associated below seen fraction " << update_reassociate_max_seen_fraction << "\n";
    o << "room_update_policy    = " << (room_policy == RoomUpdatePolicy::CurrentRoom ? "current_room" : "all") << "\n";
    o << "room_door_width_m     = " << room_door_width_m << " m\n";
    o << "room_min_area_m2      = " << room_min_area_m2 << " m^2\n";
    o << "room_search_radius_m  = " << room_search_radius_m << " m\n";
    o << "default filter: conf >= " << default_filter.min_confidence << ", range [" << default_filter.min_range_m << ", "
      << default_filter.max_range_m << "] m\n";
    for (const auto& [name, f] : per_class)
        o << "class '" << name << "': conf >= " << f.min_confidence << ", range [" << f.min_range_m << ", "
          << f.max_range_m << "] m" << (f.max_range_m <= 0 ? " (disabled)" : "") << "\n";
}

}  // namespace simp::mapping
