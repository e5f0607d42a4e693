#include <mrpt/config/CConfigFileBase.h>
#include <simp/io/NameValueList.h>
#include <simp/mapping/MappingOptions.h>

#include <sstream>
#include <stdexcept>

namespace simp::mapping {
namespace {

using io::ValueRange;
using O = MappingOptions;

// The authors' mapping_args.json (categories, omni_conf, min_dist, max_dist), but for doors: the
// authors do not map them (0, 0, 0); the project does (config_ini/mapping.ini says why).
struct AuthorsRow {
    const char* name;
    double conf, min_dist, max_dist;
};
constexpr AuthorsRow kAuthorsFilters[] = {
    {"sink", 0.7, 0.5, 3.0},     {"door", 0.7, 0.5, 4.0},         {"oven", 0.8, 0.0, 4.0},
    {"board", 0.9, 1.5, 4.5},    {"table", 0.7, 1.0, 4.5},        {"box", 0.0, 0.0, 0.0},
    {"potted plant", 0.95, 0.0, 4.5}, {"drawers", 0.8, 0.0, 3.5}, {"sofa", 0.7, 0.5, 3.0},
    {"cabinet", 0.9, 1.0, 5.0},  {"chair", 0.0, 0.0, 0.0},        {"fire extinguisher", 0.9, 0.0, 3.0},
    {"person", 0.0, 0.0, 0.0},   {"desk", 0.8, 0.5, 4.0},
};

std::string listText(const std::map<std::string, double>& m, int precision) {
    std::ostringstream s;
    s.precision(precision);
    for (const auto& [name, v] : m) s << (s.tellp() > 0 ? ", " : "") << name << ":" << v;
    return s.str();
}

bool allIn(const std::map<std::string, double>& m, const ValueRange& r) {
    for (const auto& [name, v] : m)
        if (!r.contains(v)) return false;
    return true;
}

/// A "name:value, ..." key of a per-class map: an empty value keeps the map (the defaults).
template <class Field>
void classMap(io::OptionTable<O>& t, const std::string& key, Field field, const std::string& unit, ValueRange range,
              const std::string& meaning) {
    t.custom(
        key, unit, "name:value, ... each " + range.text(), meaning,
        [field, key](O& o, const std::string& text, const std::string&) {
            if (!text.empty()) o.*field = parseClassValueList(text, key);
        },
        [field](const O& o, int precision) { return listText(o.*field, precision); },
        [field, range](const O& o) { return allIn(o.*field, range); });
}

/// class_min_confidence, class_min_range_m, class_max_range_m: one member of every per-class filter;
/// a class first named here starts from the default filter.
void classFilter(io::OptionTable<O>& t, const std::string& key, double ClassFilter::*member, const std::string& unit,
                 ValueRange range, const std::string& meaning) {
    const auto column = [member](const O& o) {
        std::map<std::string, double> m;
        for (const auto& [name, f] : o.per_class) m[name] = f.*member;
        return m;
    };
    t.custom(
        key, unit, "name:value, ... each " + range.text(), meaning,
        [member, key](O& o, const std::string& text, const std::string&) {
            if (text.empty()) return;
            for (const auto& [name, v] : parseClassValueList(text, key)) {
                auto it = o.per_class.find(name);
                if (it == o.per_class.end()) it = o.per_class.emplace(name, o.default_filter).first;
                it->second.*member = v;
            }
        },
        [column](const O& o, int precision) { return listText(column(o), precision); },
        [column, range](const O& o) { return allIn(column(o), range); });
}

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
    return io::valueOr(class_duplicate_center_radius_m, class_name, duplicate_center_radius_m);
}

double MappingOptions::crossRoomMergeRadiusOf(const std::string& class_name) const {
    return io::valueOr(class_cross_room_merge_radius_m, class_name, 0.0);
}

std::optional<WallAlignmentParams> MappingOptions::wallAlignmentOf(const std::string& class_name) const {
    const auto it = class_wall_align_max_gap_m.find(class_name);
    if (wall_align == WallAlignMode::Off || it == class_wall_align_max_gap_m.end()) return std::nullopt;
    WallAlignmentParams p = wall_alignment;
    p.max_gap_m = it->second;
    return p;
}

const io::OptionTable<MappingOptions>& MappingOptions::table() {
    static const io::OptionTable<O> t = [] {
        const auto between = ValueRange::between;
        io::OptionTable<O> t("mapping");
        t.number("trigger_dist_m", &O::trigger_dist_m, "m", between(0, 1e3), "authors' `odom_trigerTH[0]`; the paper's d_xy = 0.1 m / d_theta = 0.03 rad (Table \"Algorithm parameters\") are "
                    "the localization update triggers, the authors' mapping code uses 0.2 m / 0.1 rad")
            .number("trigger_angle_rad", &O::trigger_angle_rad, "rad", between(0, 10), "authors' `odom_trigerTH[1]`")
            .number("tau_cost", &O::tau_cost, "", between(0, 1), "authors' `costTH`")
            .number("tau_purge", &O::tau_purge, "", between(0, 1e6), "paper: empirical; purge when n_match / n_skip < 0.5")
            .flag("skip_needs_no_detection", &O::skip_needs_no_detection,
                  "a window is a miss (n_skip) only with no detection of the class at the object's place, at any confidence (false: the paper)")
            .integer("min_local_detections", &O::min_local_detections, between(1, 1e6), "authors' `totalSeenTH`")
            .number("min_local_support", &O::min_local_support, "detections per time step", between(0, 1e3),
                    "authors' `purgeDetections` (`times_matched < 0.3 detc_cnt` dropped)")
            .integer("min_confirmed_matches", &O::min_confirmed_matches, "detections", between(1, 1e6),
                     "project addition: objects with fewer are tentative, not written (\"Output: confirmed objects\")")
            .integer("min_confirmed_windows", &O::min_confirmed_windows, "integration windows", between(1, 1e6),
                     "project addition: objects matched in fewer windows are tentative too; 1 = off")
            .flag("merge_duplicates", &O::merge_duplicates, "the authors' `mergeObjects` (not in the paper; see \"Duplicate rules\")")
            .number("duplicate_tau_cost", &O::duplicate_tau_cost, "", between(0, 1), "authors' `mergeObjects(objs, 0.7)`")
            .number("duplicate_max_distance_m", &O::duplicate_max_distance_m, "m", between(0, 1e3), "authors' `mergeObjectsSingle`")
            .number("duplicate_center_radius_m", &O::duplicate_center_radius_m, "m", between(0, 1e3), "authors' `centerMerge`")
            .number("duplicate_min_overlap", &O::duplicate_min_overlap, "", between(0, 1),
                    "project rule: 3D intersection / smaller box volume; 0 = off")
            .integer("distinct_codetected_frames", &O::distinct_codetected_frames, "frames", between(0, 1e6),
                     "project rule: a same-class pair detected side by side in this many frames is never merged; 0 = off")
            .number("twin_max_support_ratio", &O::twin_max_support_ratio, "", between(0, 1),
                    "project rule: a built object with fewer than this fraction of a same-class neighbour's detections, inside its noise gate, is its twin; 0 = off")
            .number("twin_min_likelihood", &O::twin_min_likelihood, "", between(0, 1),
                    "project rule: the twin rule's gate, Eq. perclassdist likelihood of the twin's centre under the neighbour's noise")
            .number("twin_never_active_max_support_ratio", &O::twin_never_active_max_support_ratio, "", between(0, 1),
                    "project rule: twin_max_support_ratio for a built object never active in the run; 0 = off")
            .flag("remove_class_bias", &O::remove_class_bias, "project addition: map boxes = mean of detections minus the class noise mean `R_o mu` (\"Detector bias\")")
            .flag("hide_objects_in_walls", &O::hide_objects_in_walls, "project addition: on a walls-only plan, objects centred in a wall or outside are not written (\"Output: confirmed objects\")");
        classMap(t, "class_duplicate_center_radius_m", &O::class_duplicate_center_radius_m, "m", between(0, 1e3),
                 "authors' `centerMerge`");
        classMap(t, "class_cross_room_merge_radius_m", &O::class_cross_room_merge_radius_m, "m", between(0, 1e3),
                 "project rule: same-class objects of different rooms closer than this are one object (doors seen from both sides)");
        t.choice("wall_align", &O::wall_align,
                 std::vector<std::pair<std::string, WallAlignMode>>{{"auto", WallAlignMode::Auto}, {"true", WallAlignMode::On},
                                                                    {"on", WallAlignMode::On},     {"1", WallAlignMode::On},
                                                                    {"false", WallAlignMode::Off}, {"off", WallAlignMode::Off},
                                                                    {"0", WallAlignMode::Off}},
                 "project addition: the floor-plan prior (\"Wall alignment\"); `auto`: on unless the floor plan draws furniture")
            .number("wall_align_max_enclosed_unknown_m2", &O::wall_align_max_enclosed_unknown_m2, "m^2", between(0, 1e9),
                    "`auto`: more unknown area enclosed by walls than this = the plan draws furniture");
        // An explicit (even empty) list replaces the default: "class_wall_align_max_gap_m = " aligns no class.
        t.custom(
            "class_wall_align_max_gap_m", "m", "name:value, ... each in [0, 10]", "classes not listed are not aligned; an empty list aligns none",
            [](O& o, const std::string& text, const std::string&) {
                o.class_wall_align_max_gap_m =
                    text.empty() ? std::map<std::string, double>{} : parseClassValueList(text, "class_wall_align_max_gap_m");
            },
            [](const O& o, int precision) { return listText(o.class_wall_align_max_gap_m, precision); },
            [](const O& o) { return allIn(o.class_wall_align_max_gap_m, ValueRange::between(0, 10)); });
        t.number("wall_align_max_penetration_m", [](auto& o) -> auto& { return o.wall_alignment.max_penetration_m; }, "m", between(0, 10), "a side this far inside the wall is still pulled out")
            .number("wall_align_max_yaw_rad", [](auto& o) -> auto& { return o.wall_alignment.max_yaw_rad; }, "rad", between(0, 1.5), "side within this angle of parallel to the wall")
            .number("wall_align_max_residual_m", [](auto& o) -> auto& { return o.wall_alignment.max_residual_m; }, "m", between(0, 10), "straightness of the wall face along the side")
            .integer("wall_align_rays", [](auto& o) -> auto& { return o.wall_alignment.rays_per_side; }, between(2, 100), "rays per side")
            .flag("intersecting_boxes_occlude", &O::intersecting_boxes_occlude,
                  "project option: false = boxes intersecting in 3D form a group that does not occlude itself in I_active (duplicates "
                  "become active, are skipped and purged); doc/results.md")
            .number("cost_covariance_scale", &O::cost_covariance_scale, "", between(1e-6, 1e6), "C_cen covariance factor (1 = paper); doc/results.md")
            .flag("cost_uses_noise_mean", &O::cost_uses_noise_mean, "project choice: C_cen with the class bias mu (false: without)")
            .number("default_noise_sigma_m", &O::default_noise_sigma_m, "m", between(1e-6, 1e3), "C_cen of classes without a noise model")
            .number("truncation_threshold", &O::truncation_threshold, "", between(0, 1), "authors' `truncTH`")
            .number("max_occluded_fraction", &O::max_occluded_fraction, "", between(0, 1), "project choice: more of the box hidden by boxes or walls: inactive")
            .integer("zbuffer_downscale", &O::zbuffer_downscale, "px", between(1, 64), "z-buffer pixel = this many image pixels per side (80 x 60 for 640 x 480)")
            .number("wall_depth_margin_m", &O::wall_depth_margin_m, "m", between(0, 1e3), "boxes against walls stay visible")
            .number("wall_cast_max_m", &O::wall_cast_max_m, "m", between(0, 1e4), "render / ray-cast limit")
            .number("near_plane_m", &O::near_plane_m, "m", between(1e-4, 10), "camera near clipping plane")
            .number("default_fx_px", &O::default_fx_px, "px", between(1e-3, 1e6), "authors' K, for observations without intrinsics")
            .number("default_fy_px", &O::default_fy_px, "px", between(1e-3, 1e6), "authors' K")
            .number("default_cx_px", &O::default_cx_px, "px", ValueRange::finite(), "authors' K")
            .number("default_cy_px", &O::default_cy_px, "px", ValueRange::finite(), "authors' K")
            .number("default_min_confidence", [](auto& o) -> auto& { return o.default_filter.min_confidence; }, "", between(0, 1),
                    "detection filter of classes not listed")
            .number("default_min_range_m", [](auto& o) -> auto& { return o.default_filter.min_range_m; }, "m", between(0, 1e4), "detection filter of classes not listed")
            .number("default_max_range_m", [](auto& o) -> auto& { return o.default_filter.max_range_m; }, "m", between(0, 1e4), "detection filter of classes not listed")
            .integer("update_min_missed_windows", &O::update_min_missed_windows, "windows", between(1, 1e6),
                     "`--update`: an object of M0 active without a match in this many windows of the session ...")
            .number("update_max_seen_fraction", &O::update_max_seen_fraction, "", between(0, 1), "... and matched in fewer than this fraction of them is removed (\"Map update across sessions\")")
            .number("update_move_max_distance_m", &O::update_move_max_distance_m, "m", between(0, 100),
                    "a removed object with a new object of its class this close is moved")
            .number("update_min_move_m", &O::update_min_move_m, "m", between(0, 100), "closer: the object re-estimated, no change")
            .integer("update_min_new_windows", &O::update_min_new_windows, "windows", between(1, 1e6),
                     "a new object enters the updated map and the report after this many matched windows")
            .number("update_removal_alpha", &O::update_removal_alpha, "", between(0, 1),
                    "a removal also needs P(<= matched of the expected windows, given the class's match rate this session) below this (binomial)")
            .number("update_reassociate_max_seen_fraction", &O::update_reassociate_max_seen_fraction, "", between(0, 1),
                    "an object matched in fewer than this fraction of its windows (missed >= 3, unlikely for its class) is moved to a new "
                    "object of its class within `update_move_max_distance_m`, else kept")
            .number("update_unhide_max_distance_m", &O::update_unhide_max_distance_m, "m", between(0, 100),
                    "a new object this close to an object of M0 of its class does not hide it (its possible new place); the "
                    "windows that expected M0's object only so count for a move, not a removal; 0 = off")
            .number("update_twin_max_distance_m", &O::update_twin_max_distance_m, "m", between(0, 100),
                    "a new object this close to an object of M0 of its class that the session matched (or within that object's length) ...")
            .number("update_twin_max_window_ratio", &O::update_twin_max_window_ratio, "", between(0, 1e6),
                    "... and matched in fewer than this times its windows is its twin: neither added nor a move's new place; 0 = off")
            .number("update_same_overlap_fraction", &O::update_same_overlap_fraction, "", between(0, 1),
                    "a new object sharing this fraction of the smaller box's volume with an object of M0 of its class that stays "
                    "is that object seen again: neither added nor a move's new place; 0 = off")
            .number("update_same_overlap_margin_m", &O::update_same_overlap_margin_m, "m", between(0, 10),
                    "... both boxes' horizontal sides grown by this on each side first (a thin board's estimates differ across "
                    "its thickness by about its thickness)")
            .number("update_nested_overlap_fraction", &O::update_nested_overlap_fraction, "", between(0, 1),
                    "an object of M0 with this fraction of its volume inside the box of an object of another class, its top not "
                    "above that box, is never removed on misses alone (a new object of its class nearby still makes it moved); 0 = off")
            .number("update_turn_min_deg", &O::update_turn_min_deg, "deg", between(0, 45),
                    "an object of M0 whose heading this session differs from its box's by this much ...; 0 = off")
            .integer("update_turn_min_windows", &O::update_turn_min_windows, "windows", between(1, 1e6), "... over at least this many matched windows ...")
            .number("update_turn_sigmas", &O::update_turn_sigmas, "", between(0, 100),
                    "... and by this many standard errors of the session's mean heading was turned: moved, its box the session's")
            .number("room_door_width_m", &O::room_door_width_m, "m", between(0, 100), "segmentation erosion (see \"Rooms\")")
            .number("room_min_area_m2", &O::room_min_area_m2, "m^2", between(0, 1e6), "segmentation: smaller eroded components are not rooms")
            .number("room_search_radius_m", &O::room_search_radius_m, "m", between(0, 100), "room of a point in a wall")
            .number("room_behind_wall_margin_m", &O::room_behind_wall_margin_m, "m", between(0, 100),
                    "a detection of another room behind a wall, this close to the robot's room, refines objects, never starts one; 0 = paper")
            .choice("room_update_policy", &O::room_policy,
                    std::vector<std::pair<std::string, RoomUpdatePolicy>>{{"current_room", RoomUpdatePolicy::CurrentRoom},
                                                                          {"all", RoomUpdatePolicy::All}},
                    "`current_room` (paper): only objects and detections of the robot's room; `all`: no room filter");
        classFilter(t, "class_min_confidence", &ClassFilter::min_confidence, "", between(0, 1), "authors' `omni_conf` (door: project, see mapping.ini)");
        classFilter(t, "class_min_range_m", &ClassFilter::min_range_m, "m", between(0, 1e4), "authors' `min_dist` (door: project)");
        classFilter(t, "class_max_range_m", &ClassFilter::max_range_m, "m", between(0, 1e4), "authors' `max_dist`; 0 disables the class (authors: door, box, chair, person; the project maps doors)");
        t.rule("update_min_move_m", [](const O& o) { return o.update_min_move_m <= o.update_move_max_distance_m; },
               "not exceed update_move_max_distance_m");
        return t;
    }();
    return t;
}

void MappingOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) {
    // Unknown keys: io::StrictIni::checkUnknown() after loading (the keys read here are the known ones).
    table().load(c, s, *this);
}

void MappingOptions::validate() const { table().validate(*this); }

void MappingOptions::dumpToTextStream(std::ostream& o) const { table().dump(*this, o); }

}  // namespace simp::mapping
