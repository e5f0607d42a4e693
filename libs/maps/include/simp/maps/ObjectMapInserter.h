#pragma once
/// \file ObjectMapInserter.h
/// The map construction behind CObjectMap::insertObservation, as an interface: libs/maps holds
/// the map and its sensor model, the construction algorithm lives in libs/mapping, which depends
/// on this library and registers its implementation when it is loaded (libsimp_mapping.so).
/// Without a registered one, insertObservation() throws naming the library to load.

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/world/ObjectMapData.h>

#include <memory>
#include <optional>
#include <string>

namespace simp::maps {

/// The options of the registered construction algorithm: the keys of `[<prefix>_insertOpts]`.
class ObjectMapInserterOptions : public mrpt::config::CLoadableOptions {
   public:
    /// A deep copy (CObjectMap's options are values: copies of a map do not share them).
    virtual std::unique_ptr<ObjectMapInserterOptions> clone() const = 0;
};

/// One map construction run, started from a map's content; owned by one CObjectMap.
class ObjectMapInserter {
   public:
    virtual ~ObjectMapInserter() = default;
    /// Adds the detections of `obs`, the robot at `robot_pose` (world frame).
    virtual void insert(const simp::obs::CObservationObjects3D& obs, const mrpt::poses::CPose3D& robot_pose) = 0;
    /// Integrates what is pending now (the algorithm may wait for motion, as the paper's does).
    virtual void flush() = 0;
    /// The map content when it changed since the previous call (or since the start), else nullopt.
    virtual std::optional<simp::world::ObjectMapData> changedMap() = 0;
};

/// Makes the options and the runs of one construction algorithm.
class ObjectMapInserterFactory {
   public:
    virtual ~ObjectMapInserterFactory() = default;
    /// The algorithm's default options.
    virtual std::unique_ptr<ObjectMapInserterOptions> makeOptions() const = 0;
    /// A run with `options` (made by makeOptions()) starting from `start`.
    virtual std::unique_ptr<ObjectMapInserter> makeInserter(const ObjectMapInserterOptions& options,
                                                            const simp::world::ObjectMapData& start) const = 0;
};

/// Installs the factory every CObjectMap uses from now on (nullptr: none); libs/mapping calls it
/// when loaded. Thread-safe.
void setObjectMapInserterFactory(std::shared_ptr<const ObjectMapInserterFactory> factory);
/// The installed factory, or nullptr.
std::shared_ptr<const ObjectMapInserterFactory> objectMapInserterFactory();
/// The error text when none is installed: names libsimp_mapping.so and how to load it.
std::string noObjectMapInserterMessage();

}  // namespace simp::maps
