#include <simp/mapping/ObjectMapBuilder.h>
#include <simp/maps/CObjectMap.h>

namespace simp::maps {

bool CObjectMap::internal_insertObservation(const mrpt::obs::CObservation& obs,
                                            const std::optional<const mrpt::poses::CPose3D>& robotPose) {
    const auto* objects = dynamic_cast<const simp::obs::CObservationObjects3D*>(&obs);
    if (!objects) return false;  // not ours: map unchanged
    if (!m_builder) {
        // Map construction (paper Sec. "3D Semantic Map Construction") is simp::mapping's
        // ObjectMapBuilder, started from the current content. No floor plan: walls do not
        // occlude and there are no rooms (use simp-map for that).
        m_builder = std::make_shared<simp::mapping::ObjectMapBuilder>(insertionOptions.mapping);
        m_builder->setMap(m_data);
        m_synced_integrations = 0;
    }
    m_builder->insert(*objects, robotPose ? *robotPose : mrpt::poses::CPose3D());
    syncFromBuilder();
    return true;
}

void CObjectMap::flushInsertions() {
    if (!m_builder) return;
    m_builder->flush();
    syncFromBuilder();
}

void CObjectMap::syncFromBuilder() {
    // The builder's map changes when it integrates its local map (flush) or meets a new class name.
    const std::size_t integrations = m_builder->stats().integrations;
    if (integrations == m_synced_integrations && m_builder->map().class_names.size() == m_data.class_names.size())
        return;
    m_synced_integrations = integrations;
    std::lock_guard<std::mutex> lock(m_cache_mutex);
    m_data = m_builder->confirmedMap();
    m_model.reset();  // rebuilt (and validated) at the next likelihood evaluation
    m_warned_empty = false;
}

}  // namespace simp::maps
