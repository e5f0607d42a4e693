#pragma once
/// \file BuilderInserter.h
/// CObjectMap::insertObservation's map construction (maps::ObjectMapInserter): the paper's
/// ObjectMapBuilder without a floor plan. Registered when libsimp_mapping.so is loaded
/// (registerAllClasses.h); doc/architecture.md "Two ways to build a map".

#include <simp/mapping/ObjectMapBuilder.h>
#include <simp/maps/ObjectMapInserter.h>

namespace simp::mapping {

/// [<prefix>_insertOpts] of a semanticObjectMap: the MappingOptions keys (doc/mapping.md).
class BuilderInsertionOptions : public maps::ObjectMapInserterOptions {
   public:
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override {
        mapping.loadFromConfigFile(source, section);
    }
    void dumpToTextStream(std::ostream& out) const override { mapping.dumpToTextStream(out); }
    std::unique_ptr<maps::ObjectMapInserterOptions> clone() const override {
        return std::make_unique<BuilderInsertionOptions>(*this);
    }

    MappingOptions mapping;
};

/// One ObjectMapBuilder run started from a map's content. No floor plan: walls do not occlude
/// and there are no rooms (simp-map's MapApp is the full pipeline).
class BuilderInserter : public maps::ObjectMapInserter {
   public:
    BuilderInserter(const MappingOptions& options, const world::ObjectMapData& start);

    void insert(const obs::CObservationObjects3D& obs, const mrpt::poses::CPose3D& robot_pose) override;
    void flush() override;
    /// The builder's confirmed map after an integration, or when it met a new class name.
    std::optional<world::ObjectMapData> changedMap() override;

    const ObjectMapBuilder& builder() const { return m_builder; }

   private:
    ObjectMapBuilder m_builder;
    std::size_t m_shown_integrations = 0;  ///< builder integrations in the last map returned
    std::size_t m_shown_classes = 0;       ///< class count of the last map returned (or of the start)
};

}  // namespace simp::mapping
