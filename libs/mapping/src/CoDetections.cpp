#include <simp/mapping/CoDetections.h>

#include <algorithm>
#include <iterator>

namespace simp::mapping {

int sharedFrames(const FrameSerials& a, const FrameSerials& b) {
    int n = 0;
    for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end();) {
        if (*i < *j) {
            ++i;
        } else if (*j < *i) {
            ++j;
        } else {
            ++n, ++i, ++j;
        }
    }
    return n;
}

FrameSerials unionOfFrames(const FrameSerials& a, const FrameSerials& b) {
    FrameSerials out;
    out.reserve(a.size() + b.size());
    std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

void CoDetections::add(std::int64_t a, std::int64_t b, int frames) {
    if (a == b || frames <= 0) return;
    m_counts[a][b] += frames;
    m_counts[b][a] += frames;
}

int CoDetections::count(std::int64_t a, std::int64_t b) const {
    const auto it = m_counts.find(a);
    if (it == m_counts.end()) return 0;
    const auto jt = it->second.find(b);
    return jt == it->second.end() ? 0 : jt->second;
}

void CoDetections::absorb(std::int64_t into, std::int64_t from) {
    const auto it = m_counts.find(from);
    if (it == m_counts.end()) return;
    const auto partners = std::move(it->second);
    m_counts.erase(it);
    for (const auto& [other, n] : partners) {
        auto& row = m_counts[other];
        row.erase(from);
        if (other == into) continue;
        row[into] += n;
        m_counts[into][other] += n;
    }
}

void CoDetections::forget(std::int64_t id) {
    const auto it = m_counts.find(id);
    if (it == m_counts.end()) return;
    for (const auto& [other, n] : it->second) {
        (void)n;
        if (auto jt = m_counts.find(other); jt != m_counts.end()) jt->second.erase(id);
    }
    m_counts.erase(it);
}

}  // namespace simp::mapping
