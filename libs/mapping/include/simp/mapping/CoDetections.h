#pragma once
/// \file CoDetections.h
/// Which objects were detected apart: two detections of one camera frame are two objects (the
/// detector suppresses its own duplicates within an image), so a same-class pair that has been
/// detected side by side in a frame is not one object seen twice, however close its centres lie.
/// The duplicate rules (MappingOptions "distinct_codetected_frames") consult these counts; they
/// keep touching neighbours (cabinets in a row, 0.98 m apart in the authors' office) apart, which
/// the authors' centre radius (1.0 m) would merge.

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace simp::mapping {

/// The frames (serial numbers, increasing) a local object took detections from, sorted.
using FrameSerials = std::vector<std::uint32_t>;

/// Frames common to two sorted serial lists.
int sharedFrames(const FrameSerials& a, const FrameSerials& b);

/// Sorted union of two sorted serial lists (the frames of a merged local object).
FrameSerials unionOfFrames(const FrameSerials& a, const FrameSerials& b);

/// Per pair of map objects: frames in which both took a detection (symmetric).
class CoDetections {
   public:
    /// Adds `frames` to the count of the pair (a, b); a == b or frames <= 0 is ignored.
    void add(std::int64_t a, std::int64_t b, int frames);
    /// Frames in which a and b were detected together (0 when never).
    int count(std::int64_t a, std::int64_t b) const;
    /// `from` was merged into `into`: its counts become into's (summed); the pair itself is dropped.
    void absorb(std::int64_t into, std::int64_t from);
    /// Drops every count of `id` (a purged object).
    void forget(std::int64_t id);

   private:
    std::unordered_map<std::int64_t, std::unordered_map<std::int64_t, int>> m_counts;
};

}  // namespace simp::mapping
