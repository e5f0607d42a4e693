#pragma once
/// \file ObjectMapBuilder.h
/// Metric-semantic object map construction from posed 3D object detections (paper Sec.
/// "3D Semantic Map Construction"): detections aggregate into a short-term local map m^_g,
/// which is integrated into the global object map m_g after the robot moved d_xy or turned
/// d_theta (Hungarian association on Eq. costfunc, weighted merge, n_skip / n_match, purge).

#include <mrpt/poses/CPose3D.h>
#include <simp/mapping/CoDetections.h>
#include <simp/mapping/MappingOptions.h>
#include <simp/mapping/SessionTurn.h>
#include <simp/camera/FloorPlanGrid.h>
#include <simp/camera/ZBufferVisibility.h>
#include <simp/model/ObjectDistribution.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/world/ObjectMapData.h>
#include <simp/world/World.h>

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

namespace simp::mapping {

/// Counters of what the builder did (for progress output and tests).
struct BuilderStats {
    std::size_t frames = 0;              ///< insert() calls
    std::size_t detections = 0;          ///< detections seen
    std::size_t rejected_class = 0;      ///< class disabled (max range <= 0)
    std::size_t rejected_confidence = 0; ///< below the class confidence threshold
    std::size_t rejected_range = 0;      ///< outside the class range
    std::size_t rejected_room = 0;       ///< centre in another room than the robot's
    std::size_t rejected_outside = 0;    ///< centre in unknown space of the floor plan (outside the building)
    std::size_t rejected_invalid = 0;    ///< non-finite / degenerate box
    std::size_t integrations = 0;        ///< local maps integrated (flush with content)
    std::size_t merged = 0;              ///< local objects merged into map objects
    std::size_t added = 0;               ///< new map objects
    std::size_t purged = 0;              ///< map objects removed (n_match / n_skip < tau_purge)
    std::size_t duplicates_merged = 0;   ///< map objects merged into another one (merge_duplicates)
};

/// What this session saw of one map object: integration windows in which it was matched (or
/// made), and windows in which it was active (expected in view) and nothing was matched to it.
/// The evidence of a map update (MapUpdate.h), independent of the object's earlier history.
struct SessionEvidence {
    int windows_matched = 0;
    int windows_missed = 0;
    /// Updating an earlier map: windows in which it was unmatched and expected only because the
    /// new objects that may be its displaced copy (DisplacedCopies.h) were taken not to hide it.
    /// Evidence of a move to one of them, not of a removal (the new object may be a twin in front).
    int windows_missed_behind_new = 0;
};

/// One object of the short-term local map m^_g.
struct LocalObject {
    int class_id = 0;     ///< index into the map's class_names
    geometry::Box3D box;  ///< world frame, canonical upright
    int n_match = 1;      ///< detections aggregated
    /// False while it holds only detections behind a wall (MappingOptions::room_behind_wall_margin_m):
    /// it may refine a map object, never become one.
    bool may_start = true;
    FrameSerials frames;  ///< the frames of the window it took detections from (CoDetections.h)
};

class ObjectMapBuilder {
   public:
    using TOptions = MappingOptions;

    explicit ObjectMapBuilder(const TOptions& options = TOptions());

    /// The floor plan whose walls occlude, and its rooms; an empty `rooms` is replaced by
    /// segmentRooms() of the floor plan with the options' door width / minimum area.
    /// Recomputes the room id of every map object.
    void setFloorPlan(const mrpt::maps::COccupancyGridMap2D& floorplan, const world::RoomMap& rooms);
    /// Replaces the global map m_g (class list, class noise, objects); pending local map dropped.
    /// `earlier_session`: the map of an earlier session being updated (simp-map --update): a
    /// duplicate pair of one of its objects and a new one merges only when this session matched
    /// the old object (else the new one may be the old one displaced, MapUpdate.h), and the old
    /// object keeps its id. Its objects are not purged (their n_skip carries earlier sessions):
    /// detectChanges() decides on this session's evidence.
    /// \throw std::invalid_argument naming the object index when a box is invalid or its class id unknown.
    void setMap(const world::ObjectMapData& map, bool earlier_session = false);

    /// Inserts the detections of one camera frame taken with the robot at `robot_pose` (world).
    /// Several cameras of one time step are inserted one after another with the same pose.
    /// Integrates the pending local map first when the robot moved more than trigger_dist_m or
    /// turned more than trigger_angle_rad since the local map was started.
    /// Classes unknown to the map are appended to its class list (by name).
    void insert(const obs::CObservationObjects3D& obs, const mrpt::poses::CPose3D& robot_pose);
    /// Integrates the pending local map into m_g (no-op when empty).
    void flush();

    /// The whole global map m_g, tentative objects included.
    const world::ObjectMapData& map() const { return m_g; }
    /// The map to use: m_g without its tentative objects, those the builder made that have fewer
    /// than min_confirmed_matches detections (objects of the map given to setMap always stay).
    world::ObjectMapData confirmedMap() const;
    /// True for the ids of the map given to setMap (the earlier session's objects).
    bool isGivenObject(std::int64_t id) const { return id < m_first_built_id; }
    /// This session's evidence about a map object (zero when none).
    SessionEvidence evidenceOf(std::int64_t id) const;
    /// Updating an earlier map (setMap(map, true)): the boxes of the windows that matched an object
    /// this session (means of detections, with the class bias), for the turn test (SessionTurn.h),
    /// including those of the new objects merged into it; empty when not updating.
    const std::vector<SessionBox>& sessionBoxesOf(std::int64_t id) const;
    /// The map box of those windows (their weighted merge, minus the class bias, aligned to the
    /// walls): the object where this session alone saw it. nullopt without windows.
    std::optional<geometry::Box3D> sessionBoxOf(std::int64_t id) const;
    const world::RoomMap& rooms() const { return m_rooms; }
    const BuilderStats& stats() const { return m_stats; }
    TOptions& options() { return m_options; }
    const TOptions& options() const { return m_options; }

    /// Room id at a world point: the room map's, else the nearest non-zero id within
    /// room_search_radius_m; 0 when there is no room map or none is near.
    int roomOf(double x_m, double y_m) const;
    /// True when a pixel of room `room` lies within `radius_m` of the world point.
    bool roomWithin(int room, double x_m, double y_m, double radius_m) const;

    /// Whether the floor-plan prior applies: wall_align on, or auto and the floor plan draws no
    /// furniture (camera::FloorPlanGrid::enclosedUnknownArea_m2() <= wall_align_max_enclosed_unknown_m2).
    bool wallAlignmentActive() const;
    /// The floor plan draws walls only, no furniture (enclosed unknown area <=
    /// wall_align_max_enclosed_unknown_m2); false without a floor plan.
    bool planDrawsOnlyWalls() const;
    /// The camera of an observation in the world (intrinsics of the observation, else the defaults).
    camera::PinholeCamera cameraOf(const obs::CObservationObjects3D& obs, const mrpt::poses::CPose3D& robot_pose) const;

    /// Visibility of the map objects in one camera (exposed for tests): per map object, true
    /// when active (I_active = 1: in the frustum and range, not truncated, not occluded, in the
    /// current room) and true when an association candidate (in the current room, some projected
    /// pixel in the image and not behind a wall; other boxes may hide it).
    /// Updating an earlier map, `active_behind_new` (optional) marks the objects active only
    /// because their possible displaced copies (DisplacedCopies.h) do not hide them.
    void visibility(const camera::PinholeCamera& camera, int current_room, std::vector<bool>& active,
                    std::vector<bool>& candidate, std::vector<bool>* active_behind_new = nullptr);

   private:
    /// Cost of a pair that must never be associated (different classes); > any Eq. costfunc value.
    static constexpr double kForbiddenCost = 2.0;
    int mapClassOf(const std::string& name);
    /// The noise model used in C_cen (Eq. costfunc): the given model (else the isotropic default),
    /// with its mean zeroed unless cost_uses_noise_mean.
    model::NoiseModel costNoise(const std::optional<model::NoiseModel>& model) const;
    /// p_o1 of C_cen (Eq. costfunc) for a box of class `class_id`: its class's cost noise in the
    /// class noise frame.
    model::ObjectDistribution classDistribution(int class_id, const geometry::Box3D& box) const;
    /// p_o1 of C_cen for map object `o` at box `box` (its current estimate): its own noise model in
    /// its box frame when it has a valid one (imported maps), else classDistribution().
    model::ObjectDistribution objectDistribution(const world::MapObject& o, const geometry::Box3D& box) const;
    /// The class noise model's mean offset mu of a detection box, in the world (zero without a model).
    Eigen::Vector2d classBiasOf(int class_id, const geometry::Box3D& box) const;
    void insertIntoLocalMap(const std::vector<LocalObject>& detections);
    /// Eq. costfunc cost of a same-class pair when the duplicate rules (MappingOptions) make it one
    /// object, else a value > 1.
    double duplicateCost(const geometry::Box3D& o1, const model::ObjectDistribution& p_o1, int class_id,
                         const geometry::Box3D& o2) const;
    /// MappingOptions twin_max_support_ratio: `other` (built, same class) has too few detections
    /// next to `ref` and lies inside ref's noise gate, so it is ref's twin.
    bool isTwinBySupport(const world::MapObject& ref, const model::ObjectDistribution& p_ref,
                         const world::MapObject& other) const;
    void mergeLocalDuplicates();
    /// The floor-plan prior (MappingOptions wall_align): aligns the object's box to its wall.
    void alignToFloorPlan(world::MapObject& o) const;
    geometry::Box3D alignedBox(int class_id, const geometry::Box3D& box) const;
    /// Merges duplicates among the map objects with the given ids; returns how many were removed.
    std::size_t mergeMapDuplicates(const std::set<std::int64_t>& ids);

    TOptions m_options;
    world::ObjectMapData m_g;       ///< the global object map m_g
    std::vector<LocalObject> m_local;  ///< the local map m^_g
    /// Detections of the window under their class's confidence threshold (world frame; they are
    /// no evidence for the map, but no miss of an object at their place: skip_needs_no_detection).
    std::vector<LocalObject> m_window_weak;
    std::set<std::int64_t> m_window_active;     ///< map ids active in some frame of the window
    std::set<std::int64_t> m_window_active_behind_new;  ///< of those, ids never active but behind a possible displaced copy
    std::set<std::int64_t> m_window_candidates; ///< map ids visible in some frame of the window
    std::optional<mrpt::poses::CPose3D> m_window_start;  ///< robot pose when m^_g was started
    int m_window_room = 0;  ///< the robot's room in the window's last frame (0 = unknown / policy all)
    std::size_t m_window_steps = 0;  ///< time steps (robot pose or stamp changed) in the window
    /// Stamp and robot pose of the last inserted frame.
    std::optional<std::pair<mrpt::Clock::time_point, mrpt::poses::CPose3D>> m_last_step;
    std::int64_t m_next_id = 1;
    std::int64_t m_first_built_id = 1;  ///< ids below were given by setMap (never tentative)
    /// remove_class_bias: each built object's mean of detections, its state for association and
    /// merging; its box in m_g is shownBox(mean). Absent (objects of setMap, option off): the box
    /// plus the class bias (the box minus nothing when the option is off).
    std::unordered_map<std::int64_t, geometry::Box3D> m_estimates;
    std::unordered_map<std::int64_t, int> m_windows_matched;  ///< integrations that matched or made the object
    std::unordered_map<std::int64_t, int> m_windows_missed;   ///< integrations where it was active and unmatched
    std::unordered_map<std::int64_t, int> m_windows_active;   ///< integrations where it was active (matched or not)
    std::unordered_map<std::int64_t, int> m_windows_missed_behind_new;  ///< SessionEvidence::windows_missed_behind_new
    bool m_earlier_session = false;                           ///< setMap(map, true): updating an earlier map
    std::unordered_map<std::int64_t, std::vector<SessionBox>> m_session_boxes;  ///< sessionBoxesOf()
    CoDetections m_codetections;  ///< frames in which two map objects took a detection each
    /// A pair detected side by side in this many frames is two objects (distinct_codetected_frames).
    bool detectedApart(int shared_frames) const;
    geometry::Box3D estimateOf(const world::MapObject& o) const;
    void forget(std::int64_t id);  ///< drops the per-object state of a purged or merged-away object
    /// The map box of a mean of detections: minus the class bias, aligned to the walls.
    geometry::Box3D shownBox(int class_id, const geometry::Box3D& estimate) const;
    void setEstimate(world::MapObject& o, const geometry::Box3D& estimate);

    camera::FloorPlanGrid m_walls;
    world::RoomMap m_rooms;
    camera::ZBufferRenderer m_renderer;
    std::vector<geometry::Box3D> m_boxes_scratch;
    std::vector<char> m_occludes_scratch;  ///< per object: 0 for doors (camera/Occluders.h)
    std::vector<camera::BoxView> m_views_scratch;
    /// Per map object: id of its group of mutually intersecting boxes (they do not occlude each
    /// other in I_active); recomputed after the map changed.
    std::vector<int> m_groups;
    bool m_groups_valid = false;
    void updateGroups();
    /// Updating an earlier map: per map object, the new objects that do not hide it (its possible
    /// displaced copies, DisplacedCopies.h); recomputed after the map changed.
    std::vector<std::vector<int>> m_unhidden_by;
    bool m_unhidden_valid = false;
    BuilderStats m_stats;
};

}  // namespace simp::mapping
