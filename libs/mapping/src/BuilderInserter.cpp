#include <simp/mapping/BuilderInserter.h>

namespace simp::mapping {

BuilderInserter::BuilderInserter(const MappingOptions& options, const world::ObjectMapData& start)
    : m_builder(options), m_shown_classes(start.class_names.size()) {
    m_builder.setMap(start);
}

void BuilderInserter::insert(const obs::CObservationObjects3D& obs, const mrpt::poses::CPose3D& robot_pose) {
    m_builder.insert(obs, robot_pose);
}

void BuilderInserter::flush() { m_builder.flush(); }

std::optional<world::ObjectMapData> BuilderInserter::changedMap() {
    // The builder's map changes when it integrates its local map (flush) or meets a new class name.
    const std::size_t integrations = m_builder.stats().integrations;
    if (integrations == m_shown_integrations && m_builder.map().class_names.size() == m_shown_classes)
        return std::nullopt;
    m_shown_integrations = integrations;
    auto map = m_builder.confirmedMap();
    m_shown_classes = map.class_names.size();
    return map;
}

}  // namespace simp::mapping
