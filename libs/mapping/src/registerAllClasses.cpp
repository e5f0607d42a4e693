#include <mrpt/core/initializer.h>
#include <simp/mapping/BuilderInserter.h>
#include <simp/mapping/registerAllClasses.h>

// Loading libsimp_mapping.so gives every CObjectMap (libsimp_maps.so, which does not depend on
// this library) its insertObservation: MRPT's tools get map construction by loading this plugin.
MRPT_INITIALIZER(registerAllClasses_simp_mapping) { simp::mapping::registerAllClasses(); }

namespace simp::mapping {
namespace {

class BuilderInserterFactory : public maps::ObjectMapInserterFactory {
   public:
    std::unique_ptr<maps::ObjectMapInserterOptions> makeOptions() const override {
        return std::make_unique<BuilderInsertionOptions>();
    }
    std::unique_ptr<maps::ObjectMapInserter> makeInserter(const maps::ObjectMapInserterOptions& options,
                                                          const world::ObjectMapData& start) const override {
        return std::make_unique<BuilderInserter>(dynamic_cast<const BuilderInsertionOptions&>(options).mapping, start);
    }
};

/// The factory this library installs; unloading the library (MRPT's tools dlclose their plugins at
/// exit) takes its code away, so it uninstalls it first.
struct Installation {
    std::shared_ptr<const maps::ObjectMapInserterFactory> factory = std::make_shared<const BuilderInserterFactory>();
    ~Installation() {
        if (maps::objectMapInserterFactory() == factory) maps::setObjectMapInserterFactory(nullptr);
    }
};

Installation& installation() {
    static Installation i;
    return i;
}

}  // namespace

void registerAllClasses() { maps::setObjectMapInserterFactory(installation().factory); }

}  // namespace simp::mapping
