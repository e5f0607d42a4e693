// ObjectMapBuilder: set-up, per-frame insertion and the short-term local map m^_g.
// The integration into m_g is in ObjectMapBuilder_integrate.cpp, visibility in
// ObjectMapBuilder_visibility.cpp.
#include <mrpt/math/wrap2pi.h>
#include <mrpt/system/datetime.h>
#include <simp/geometry/Hungarian.h>
#include <simp/mapping/AssociationCost.h>
#include <simp/mapping/DetectionBox.h>
#include <simp/mapping/ObjectMapBuilder.h>
#include <simp/mapping/RoomSegmentation.h>
#include <simp/model/NoiseFrame.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace simp::mapping {

ObjectMapBuilder::ObjectMapBuilder(const TOptions& options) : m_options(options) { m_options.validate(); }

void ObjectMapBuilder::setFloorPlan(const mrpt::maps::COccupancyGridMap2D& floorplan, const world::RoomMap& rooms) {
    m_walls = camera::FloorPlanGrid(floorplan);
    if (!rooms.empty()) {
        m_rooms = rooms;
    } else {
        RoomSegmentationParams p;
        p.door_width_m = m_options.room_door_width_m;
        p.min_room_area_m2 = m_options.room_min_area_m2;
        m_rooms = segmentRooms(floorplan, p);
    }
    for (auto& o : m_g.objects) o.room_id = roomOf(o.box.center.x(), o.box.center.y());
}

void ObjectMapBuilder::setMap(const world::ObjectMapData& map, bool earlier_session) {
    world::ObjectMapData g = map;
    g.class_noise.resize(g.class_names.size());
    std::int64_t max_id = 0;
    for (std::size_t i = 0; i < g.objects.size(); ++i) {
        auto& o = g.objects[i];
        if (o.class_id < 0 || static_cast<std::size_t>(o.class_id) >= g.class_names.size())
            throw std::invalid_argument("ObjectMapBuilder::setMap: object " + std::to_string(i) + " (id " +
                                        std::to_string(o.id) + ") has unknown class id " + std::to_string(o.class_id));
        if (!o.box.isValid(1e-4))
            throw std::invalid_argument("ObjectMapBuilder::setMap: object " + std::to_string(i) + " (id " +
                                        std::to_string(o.id) + ") has an invalid box (NaN, size <= 0 or not a rotation)");
        o.box = geometry::canonicalizeUpright(o.box);
        o.room_id = roomOf(o.box.center.x(), o.box.center.y());
        max_id = std::max(max_id, o.id);
    }
    m_g = std::move(g);
    m_next_id = max_id + 1;
    m_first_built_id = m_next_id;
    m_estimates.clear();
    m_windows_matched.clear();
    m_windows_missed.clear();
    m_windows_missed_behind_new.clear();
    m_session_boxes.clear();
    m_codetections = CoDetections();  // pairs of the replaced map's ids
    m_earlier_session = earlier_session;
    m_local.clear();
    m_window_weak.clear();
    m_window_active.clear();
    m_window_active_behind_new.clear();
    m_window_candidates.clear();
    m_window_start.reset();
    m_window_steps = 0;
    m_last_step.reset();
    m_groups_valid = false;
    m_unhidden_valid = false;
}

SessionEvidence ObjectMapBuilder::evidenceOf(std::int64_t id) const {
    SessionEvidence e;
    if (const auto it = m_windows_matched.find(id); it != m_windows_matched.end()) e.windows_matched = it->second;
    if (const auto it = m_windows_missed.find(id); it != m_windows_missed.end()) e.windows_missed = it->second;
    if (const auto it = m_windows_missed_behind_new.find(id); it != m_windows_missed_behind_new.end())
        e.windows_missed_behind_new = it->second;
    return e;
}

const std::vector<SessionBox>& ObjectMapBuilder::sessionBoxesOf(std::int64_t id) const {
    static const std::vector<SessionBox> kNone;
    const auto it = m_session_boxes.find(id);
    return it == m_session_boxes.end() ? kNone : it->second;
}

std::optional<geometry::Box3D> ObjectMapBuilder::sessionBoxOf(std::int64_t id) const {
    const auto& windows = sessionBoxesOf(id);
    const auto o = std::find_if(m_g.objects.begin(), m_g.objects.end(), [id](const auto& m) { return m.id == id; });
    if (windows.empty() || o == m_g.objects.end()) return std::nullopt;
    geometry::Box3D mean = windows.front().box;
    double weight = windows.front().weight;
    for (std::size_t k = 1; k < windows.size(); ++k) {
        mean = mergeBoxes(mean, weight, windows[k].box, windows[k].weight);
        weight += windows[k].weight;
    }
    return shownBox(o->class_id, mean);
}

world::ObjectMapData ObjectMapBuilder::confirmedMap() const {
    world::ObjectMapData out = m_g;
    // Objects of the map it was given (setMap) are established content; only those the builder
    // made wait for their confirmation.
    const auto tentative = [&](const world::MapObject& o) {
        if (o.id < m_first_built_id) return false;
        if (o.n_match < m_options.min_confirmed_matches) return true;
        if (m_options.min_confirmed_windows > 1) {
            const auto it = m_windows_matched.find(o.id);
            if (it == m_windows_matched.end() || it->second < m_options.min_confirmed_windows) return true;
        }
        // An estimate inside a wall or outside the building is no furniture the robot could see.
        const double x = o.box.center.x(), y = o.box.center.y();
        return m_options.hide_objects_in_walls && planDrawsOnlyWalls() && (m_walls.isWall(x, y) || m_walls.isOutside(x, y));
    };
    out.objects.erase(std::remove_if(out.objects.begin(), out.objects.end(), tentative), out.objects.end());
    // Twins by support (MappingOptions twin_max_support_ratio), judged on the whole run's counts:
    // during the run a real object seen late would lose to a neighbour seen early.
    if (m_options.twin_max_support_ratio > 0 || m_options.twin_never_active_max_support_ratio > 0) {
        std::vector<char> twin(out.objects.size(), 0);
        for (std::size_t i = 0; i < out.objects.size(); ++i) {
            const world::MapObject& ref = out.objects[i];
            if (isGivenObject(ref.id)) continue;
            const model::ObjectDistribution p_ref = objectDistribution(ref, ref.box);
            for (std::size_t k = 0; k < out.objects.size(); ++k)
                if (k != i && out.objects[k].class_id == ref.class_id && isTwinBySupport(ref, p_ref, out.objects[k])) twin[k] = 1;
        }
        std::size_t w = 0;
        for (std::size_t k = 0; k < out.objects.size(); ++k)
            if (!twin[k]) out.objects[w++] = out.objects[k];
        out.objects.resize(w);
    }
    return out;
}

bool ObjectMapBuilder::isTwinBySupport(const world::MapObject& ref, const model::ObjectDistribution& p_ref,
                                       const world::MapObject& other) const {
    if ((m_options.twin_max_support_ratio <= 0 && m_options.twin_never_active_max_support_ratio <= 0) || isGivenObject(ref.id) ||
        isGivenObject(other.id))
        return false;
    // Objects of different rooms are never one (the room rule), and one seen only from the other
    // side of a wall is seen less.
    if (ref.room_id != 0 && other.room_id != 0 && ref.room_id != other.room_id) return false;
    const auto active = m_windows_active.find(other.id);
    const bool never_active = active == m_windows_active.end() || active->second == 0;
    const double ratio = never_active ? std::max(m_options.twin_max_support_ratio, m_options.twin_never_active_max_support_ratio)
                                      : m_options.twin_max_support_ratio;
    if (static_cast<double>(other.n_match) >= ratio * static_cast<double>(ref.n_match)) return false;
    return p_ref.probability(other.box.center.x(), other.box.center.y()) >= m_options.twin_min_likelihood;
}

int ObjectMapBuilder::roomOf(double x_m, double y_m) const {
    int row = 0, col = 0;
    if (m_rooms.empty() || !m_rooms.pixelOf(x_m, y_m, row, col)) return 0;
    if (const int id = m_rooms.roomAtPixel(row, col)) return id;
    // Nearest labelled pixel within the search radius (objects stand against walls; the GT
    // floor plans mark furniture footprints as occupied).
    const int rad = static_cast<int>(std::ceil(m_options.room_search_radius_m / m_rooms.resolution_m));
    int best = 0, best_d2 = rad * rad + 1;
    for (int dr = -rad; dr <= rad; ++dr)
        for (int dc = -rad; dc <= rad; ++dc) {
            const int d2 = dr * dr + dc * dc;
            if (d2 >= best_d2) continue;
            if (const int id = m_rooms.roomAtPixel(row + dr, col + dc)) best = id, best_d2 = d2;
        }
    return best;
}

bool ObjectMapBuilder::roomWithin(int room, double x_m, double y_m, double radius_m) const {
    int row = 0, col = 0;
    if (m_rooms.empty() || radius_m <= 0 || !m_rooms.pixelOf(x_m, y_m, row, col)) return false;
    const int rad = static_cast<int>(std::ceil(radius_m / m_rooms.resolution_m));
    for (int dr = -rad; dr <= rad; ++dr)
        for (int dc = -rad; dc <= rad; ++dc)
            if (dr * dr + dc * dc <= rad * rad && m_rooms.roomAtPixel(row + dr, col + dc) == room) return true;
    return false;
}

int ObjectMapBuilder::mapClassOf(const std::string& name) {
    const int id = m_g.classId(name);
    if (id >= 0) return id;
    m_g.class_names.push_back(name);
    m_g.class_noise.resize(m_g.class_names.size());
    return static_cast<int>(m_g.class_names.size()) - 1;
}

model::NoiseModel ObjectMapBuilder::costNoise(const std::optional<model::NoiseModel>& model) const {
    model::NoiseModel n;
    if (model && model->isValid()) {
        n = *model;
    } else {  // classes without a model: isotropic Gaussian
        n.cov_m2 = Eigen::Matrix2d::Identity() * m_options.default_noise_sigma_m * m_options.default_noise_sigma_m;
        n.exponent_b = 2.0;
    }
    // Both objects of the cost are predictions (a map / local object is a mean of detections):
    // the detector's bias mu cancels in their difference.
    if (!m_options.cost_uses_noise_mean) n.mean_m.setZero();
    n.cov_m2 *= m_options.cost_covariance_scale;  // both objects are estimates (MappingOptions.h)
    return n;
}

model::ObjectDistribution ObjectMapBuilder::classDistribution(int class_id, const geometry::Box3D& box) const {
    const bool modelled = class_id >= 0 && static_cast<std::size_t>(class_id) < m_g.class_noise.size();
    return model::makeObjectDistribution(box, costNoise(modelled ? m_g.class_noise[class_id] : std::nullopt),
                                         model::NoiseSource::Class);
}

model::ObjectDistribution ObjectMapBuilder::objectDistribution(const world::MapObject& o,
                                                               const geometry::Box3D& box) const {
    // An object's own noise is in its box frame (model::NoiseFrame.h), not the class noise frame.
    if (o.noise && o.noise->isValid())
        return model::makeObjectDistribution(box, costNoise(o.noise), model::NoiseSource::Object);
    return classDistribution(o.class_id, box);
}

Eigen::Vector2d ObjectMapBuilder::classBiasOf(int class_id, const geometry::Box3D& box) const {
    const auto c = static_cast<std::size_t>(class_id);
    if (class_id < 0 || c >= m_g.class_noise.size() || !m_g.class_noise[c] || !m_g.class_noise[c]->isValid())
        return Eigen::Vector2d::Zero();
    // Eq. shiftdist: a detection's centre is offset by R_o mu from the object's (class noise frame).
    return Eigen::Rotation2Dd(model::classNoiseFrameYaw(box)) * m_g.class_noise[c]->mean_m;
}

camera::PinholeCamera ObjectMapBuilder::cameraOf(const obs::CObservationObjects3D& obs,
                                                 const mrpt::poses::CPose3D& robot_pose) const {
    // The observation's image size with its intrinsics, or the configured default intrinsics.
    const auto fallback = camera::makeIntrinsics(0, 0, m_options.default_fx_px, m_options.default_fy_px,
                                                 m_options.default_cx_px, m_options.default_cy_px);
    return camera::PinholeCamera::onRobot(
        robot_pose, obs.cameraPose(),
        camera::imageIntrinsics(obs.intrinsics(), static_cast<int>(obs.imageWidth()),
                                static_cast<int>(obs.imageHeight()), fallback));
}

void ObjectMapBuilder::insert(const obs::CObservationObjects3D& obs, const mrpt::poses::CPose3D& robot_pose) {
    ++m_stats.frames;
    // Integration trigger: moved more than d_xy or turned more than d_theta since m^_g started.
    if (m_window_start) {
        const double dxy = std::hypot(robot_pose.x() - m_window_start->x(), robot_pose.y() - m_window_start->y());
        const double dth = std::abs(mrpt::math::wrapToPi(robot_pose.yaw() - m_window_start->yaw()));
        if (dxy > m_options.trigger_dist_m || dth > m_options.trigger_angle_rad) flush();
    }
    if (!m_window_start) m_window_start = robot_pose;
    // The window's support counts time steps: the cameras of one step come with the same robot
    // pose and stamps within a few milliseconds of each other.
    const bool same_step = m_last_step && m_window_steps > 0 && m_last_step->second == robot_pose &&
                           std::abs(mrpt::system::timeDifference(m_last_step->first, obs.timestamp)) < 0.05;
    if (!same_step) ++m_window_steps;
    m_last_step = {obs.timestamp, robot_pose};

    const int current_room =
        m_options.room_policy == RoomUpdatePolicy::All ? 0 : roomOf(robot_pose.x(), robot_pose.y());
    m_window_room = current_room;

    // I_active of the map objects for this camera, accumulated over the window.
    const camera::PinholeCamera camera = cameraOf(obs, robot_pose);
    std::vector<bool> active, candidate, behind_new;
    visibility(camera, current_room, active, candidate, &behind_new);
    for (std::size_t k = 0; k < m_g.objects.size(); ++k) {
        if (active[k]) (behind_new[k] ? m_window_active_behind_new : m_window_active).insert(m_g.objects[k].id);
        if (candidate[k]) m_window_candidates.insert(m_g.objects[k].id);
    }

    // Detections: class / confidence / range filter, to the world, canonical upright, room filter.
    std::vector<LocalObject> dets;
    for (std::size_t i = 0; i < obs.size(); ++i) {
        ++m_stats.detections;
        const obs::Detection3D& d = obs.detections()[i];
        const std::string& name = obs.classNameOf(d);
        const ClassFilter& f = m_options.filterOf(name);
        if (f.max_range_m <= 0) { ++m_stats.rejected_class; continue; }
        // A weak detection (under the class's confidence) passes the other filters silently: kept
        // aside, it only tells the purge rule that the object at its place was seen.
        const bool weak = d.confidence < f.min_confidence;
        if (weak) ++m_stats.rejected_confidence;
        if (weak && !m_options.skip_needs_no_detection) continue;
        const auto reject = [&](std::size_t& counter) {
            if (!weak) ++counter;
        };
        const double range = d.box_in_camera.center.norm();
        if (range < f.min_range_m || range > f.max_range_m) { reject(m_stats.rejected_range); continue; }
        LocalObject o;
        o.box = objectBoxFromDetection(obs.boxInWorld(i, robot_pose));
        if (!o.box.isValid(1e-4)) { reject(m_stats.rejected_invalid); continue; }
        // A centre outside the building (unknown space reached from the plan's border, behind the
        // outer wall) is a depth error: the room lookup's search radius would otherwise give it the
        // room next to it. Unknown islands inside (furniture drawn grey) are not outside.
        if (m_walls.isOutside(o.box.center.x(), o.box.center.y())) {
            reject(m_stats.rejected_outside);
            continue;
        }
        if (current_room != 0) {
            const int r = roomOf(o.box.center.x(), o.box.center.y());
            if (r != 0 && r != current_room) {
                const Eigen::Vector2d cam = camera.world_T_camera.translation().head<2>();
                const Eigen::Vector2d to = o.box.center.head<2>() - cam;
                const bool behind_wall = !m_walls.empty() && m_walls.castRay(cam, to, to.norm()) < to.norm();
                if (!behind_wall ||
                    !roomWithin(current_room, o.box.center.x(), o.box.center.y(), m_options.room_behind_wall_margin_m)) {
                    reject(m_stats.rejected_room);
                    continue;
                }
                o.may_start = false;
            }
        }
        o.class_id = mapClassOf(name);
        o.frames = {static_cast<std::uint32_t>(m_stats.frames)};
        (weak ? m_window_weak : dets).push_back(o);
    }
    insertIntoLocalMap(dets);
}

void ObjectMapBuilder::insertIntoLocalMap(const std::vector<LocalObject>& dets) {
    if (dets.empty()) return;
    const std::size_t n_local = m_local.size();
    std::vector<int> assignment(dets.size(), -1);
    if (n_local > 0) {
        // Association across frames with the same cost as the map (Eq. costfunc), o1 = local object.
        Eigen::MatrixXd cost(dets.size(), n_local);
        for (std::size_t r = 0; r < dets.size(); ++r)
            for (std::size_t c = 0; c < n_local; ++c)
                cost(r, c) = dets[r].class_id != m_local[c].class_id
                                 ? kForbiddenCost
                                 : associationCost(m_local[c].box, classDistribution(m_local[c].class_id, m_local[c].box), dets[r].box);
        assignment = geometry::solveAssignment(cost);
        for (std::size_t r = 0; r < dets.size(); ++r)
            if (assignment[r] >= 0 && !(cost(r, assignment[r]) < m_options.tau_cost)) assignment[r] = -1;
    }
    for (std::size_t r = 0; r < dets.size(); ++r) {
        if (assignment[r] < 0) {
            m_local.push_back(dets[r]);
            continue;
        }
        LocalObject& l = m_local[assignment[r]];
        l.box = mergeBoxes(l.box, l.n_match, dets[r].box, dets[r].n_match);
        l.n_match += dets[r].n_match;
        l.may_start = l.may_start || dets[r].may_start;
        l.frames = unionOfFrames(l.frames, dets[r].frames);
    }
}

}  // namespace simp::mapping
