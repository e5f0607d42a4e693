#include <simp/maps/CObjectMap.h>

#include <stdexcept>

namespace simp::maps {

bool CObjectMap::internal_insertObservation(const mrpt::obs::CObservation& obs,
                                            const std::optional<const mrpt::poses::CPose3D>& robotPose) {
    const auto* objects = dynamic_cast<const simp::obs::CObservationObjects3D*>(&obs);
    if (!objects) return false;  // not ours: map unchanged
    if (!m_inserter) {
        // Map construction (paper Sec. "3D Semantic Map Construction") is not this library's:
        // libsimp_mapping.so registers simp::mapping's ObjectMapBuilder (ObjectMapInserter.h),
        // which starts from the current content.
        const auto factory = objectMapInserterFactory();
        if (!factory) throw std::runtime_error(noObjectMapInserterMessage());
        m_inserter = factory->makeInserter(insertionOptions.resolve(*factory), m_data);
    }
    m_inserter->insert(*objects, robotPose ? *robotPose : mrpt::poses::CPose3D());
    syncFromInserter();
    return true;
}

void CObjectMap::flushInsertions() {
    if (!m_inserter) return;
    m_inserter->flush();
    syncFromInserter();
}

void CObjectMap::syncFromInserter() {
    auto changed = m_inserter->changedMap();
    if (!changed) return;
    std::lock_guard<std::mutex> lock(m_cache_mutex);
    m_data = std::move(*changed);
    m_model.reset();  // rebuilt (and validated) at the next likelihood evaluation
    m_warned_empty = false;
}

}  // namespace simp::maps
