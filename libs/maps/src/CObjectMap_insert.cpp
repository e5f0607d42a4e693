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
    const simp::world::ObjectMapData built = m_builder->confirmedMap();
    const bool changed = built.objects.size() != m_data.objects.size() ||
                         built.class_names.size() != m_data.class_names.size() ||
                         m_builder->stats().integrations > 0;
    if (!changed) return;
    std::lock_guard<std::mutex> lock(m_cache_mutex);
    m_data = built;
    m_model.reset();  // rebuilt (and validated) at the next likelihood evaluation
    m_warned_empty = false;
}

}  // namespace simp::maps
