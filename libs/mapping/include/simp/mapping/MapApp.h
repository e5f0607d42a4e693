#pragma once
/// \file MapApp.h
/// The simp-map program as a library class (thin main, testable in-process):
///   simp-map --world W --rawlog Q/sequence.rawlog --poses Q/groundtruth.tum --out M
///            [--config INI] [--odometry-only] [--3dscene F] [--update M0]
/// reads the floor plan (+ rooms) of W, maps the 3D detections of the rawlog at the poses of
/// the TUM file (or of the integrated odometry) and writes the world directory M.

#include <simp/io/CommandLine.h>
#include <simp/mapping/MapUpdate.h>
#include <simp/mapping/ObjectMapBuilder.h>
#include <simp/world/World.h>

#include <iosfwd>
#include <string>

namespace simp::mapping {

struct MapAppArgs {
    std::string world_dir;     ///< W: its floor plan (+ rooms.png, + class noise of objects.json) is used
    std::string rawlog_path;   ///< Q/sequence.rawlog (actions + sensory frames, or observations only)
    std::string poses_path;    ///< Q/groundtruth.tum (robot poses by timestamp)
    std::string out_dir;       ///< M
    std::string config_path;   ///< optional .ini, section [mapping]
    bool odometry_only = false;  ///< poses from the rawlog's odometry, starting at the first TUM pose
    std::string scene_path;    ///< --3dscene: MRPT .3Dscene of the built map (empty = none)
    std::string update_dir;    ///< --update M0: the map of an earlier session to update (empty = build anew)
};

class MapApp {
   public:
    /// Parses the command line. Returns false when --help / --version was printed (nothing to run).
    /// \throw std::invalid_argument with the parser's message on bad arguments.
    bool initialize(int argc, const char* const* argv);
    /// The declared options (the --help text and the checks derive from them).
    static io::CommandLine commandLine();
    /// Same with parsed arguments; loads and validates the configuration.
    /// \throw std::runtime_error / std::invalid_argument naming the missing file or bad key.
    void initialize(const MapAppArgs& args);
    /// Builds the map and writes M (objects.json, floorplan.yaml/.png, rooms.png, map.png) and the
    /// --3dscene file (floor plan, built objects, the poses file as ground truth, the odometry path
    /// with --odometry-only).
    void run();

    const ObjectMapBuilder& builder() const { return m_builder; }
    const MapAppArgs& args() const { return m_args; }
    std::size_t framesMapped() const { return m_frames_mapped; }
    /// --update: the changes detected against M0 (empty otherwise).
    const MapUpdateResult& update() const { return m_update; }

    std::ostream* log;  ///< progress and summary (default std::cout)

    MapApp();

   private:
    world::World loadFloorPlanWorld() const;
    /// The earlier map M0 (--update), its errors prefixed with "--update map 'M0'".
    world::World loadEarlierMap() const;

    MapAppArgs m_args;
    ObjectMapBuilder m_builder;
    std::size_t m_frames_mapped = 0, m_frames_without_pose = 0;
    MapUpdateResult m_update;
};

}  // namespace simp::mapping
