#include <simp/maps/ObjectMapInserter.h>

#include <mutex>

namespace simp::maps {
namespace {

struct Registry {
    std::mutex mutex;
    std::shared_ptr<const ObjectMapInserterFactory> factory;
};

// Made on first use, so that a library registering from its initializer never meets it
// unconstructed; never destroyed, so that a plugin unregistering from its destructor at exit
// (MRPT unloads plugins then) never meets it destroyed.
Registry& registry() {
    static Registry* const r = new Registry;
    return *r;
}

}  // namespace

void setObjectMapInserterFactory(std::shared_ptr<const ObjectMapInserterFactory> factory) {
    auto& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    r.factory = std::move(factory);
}

std::shared_ptr<const ObjectMapInserterFactory> objectMapInserterFactory() {
    auto& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    return r.factory;
}

std::string noObjectMapInserterMessage() {
    return "simp::maps::CObjectMap::insertObservation: no map construction is loaded. It is "
           "simp::mapping's ObjectMapBuilder in libsimp_mapping.so: load it as a plugin (RawLogViewer -l "
           "libsimp_mapping.so, rawlog-edit --plugins libsimp_obs.so,libsimp_maps.so,libsimp_mapping.so, "
           "LD_PRELOAD=...:libsimp_mapping.so) or link the program with simp::mapping (doc/plugin.md)";
}

}  // namespace simp::maps
