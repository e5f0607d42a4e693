#include <simp/localization/RawlogSequence.h>

#include <mrpt/core/exceptions.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <new>
#include <simp/obs/BoundedArchive.h>
#include <mrpt/system/filesystem.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace simp::localization {
namespace {

std::optional<double> timeOf(mrpt::Clock::time_point t) {
    if (t == INVALID_TIMESTAMP) return std::nullopt;
    return mrpt::Clock::toDouble(t);
}

/// Motion of one action collection (identity when it holds no 2D movement).
mrpt::poses::CPose2D incrementOf(const mrpt::obs::CActionCollection& acts) {
    const auto mv = acts.getBestMovementEstimation();
    if (!mv) return {};
    if (mv->estimationMethod == mrpt::obs::CActionRobotMovement2D::emOdometry) return mv->rawOdometryIncrementReading;
    return mrpt::poses::CPose2D(mv->poseChange.get_ptr()->getMeanVal());
}

/// Builds frames from entries of either format, in file order.
class FrameBuilder {
   public:
    FrameBuilder(RawlogSequence& seq, const std::string& path) : m_seq(seq), m_path(path) {}

    void action(const mrpt::obs::CActionCollection& acts) {
        m_seq.format = "actions+sensoryframes";
        m_pending_increment = m_pending_increment + incrementOf(acts);
        if (!m_action_time) {
            for (const auto& a : acts) {
                if (const auto t = timeOf(a->timestamp)) {
                    m_action_time = t;
                    break;
                }
            }
        }
    }

    void sensoryFrame(const mrpt::obs::CSensoryFrame::Ptr& sf) {
        std::optional<double> t;
        for (const auto& o : *sf) {
            if ((t = timeOf(o->timestamp))) break;
        }
        if (!t) t = m_action_time;
        push(sf, t, m_seq.entries - 1);
        m_action_time.reset();
    }

    void observation(const mrpt::obs::CObservation::Ptr& obs) {
        if (m_seq.format.empty()) m_seq.format = "observations";
        const auto t = timeOf(obs->timestamp);
        if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs)) {
            if (m_pending_sf && t && m_pending_time && *t > *m_pending_time) flushObservations();
            m_last_odometry = odo->odometry;
            return;
        }
        if (m_pending_sf && t != m_pending_time) flushObservations();
        if (!m_pending_sf) {
            m_pending_sf = mrpt::obs::CSensoryFrame::Create();
            m_pending_time = t;
            m_pending_entry = m_seq.entries - 1;
        }
        m_pending_sf->insert(obs);
    }

    void finish() { flushObservations(); }

   private:
    void flushObservations() {
        if (!m_pending_sf) return;
        if (m_last_odometry) {
            if (m_odometry_at_last_frame) m_pending_increment = *m_last_odometry - *m_odometry_at_last_frame;
            m_odometry_at_last_frame = m_last_odometry;
        }
        push(m_pending_sf, m_pending_time, m_pending_entry);
        m_pending_sf.reset();
        m_pending_time.reset();
    }

    /// Appends a frame; `entry` (0-based rawlog entry) names it when its time goes backwards.
    void push(const mrpt::obs::CSensoryFrame::Ptr& sf, std::optional<double> t, std::size_t entry) {
        if (t && m_last_time && *t <= *m_last_time) {
            // The filter's steps, estimate.tum and the metrics need increasing times; MRPT's
            // `rawlog-edit --remap-timestamps` moves observations but not actions, and a shuffled
            // or merged rawlog can reorder frames: refuse rather than guess the order.
            char msg[320];
            std::snprintf(msg, sizeof(msg),
                          "entry %zu (frame %zu): time stamp %.6f s is not after the previous frame's %.6f s "
                          "(entry %zu); frame times must increase",
                          entry, m_seq.frames.size(), *t, *m_last_time, m_last_entry);
            throw std::runtime_error("rawlog '" + m_path + "': " + msg);
        }
        if (t) m_last_time = t, m_last_entry = entry;
        SequenceFrame f;
        f.t_s = t ? *t : static_cast<double>(m_seq.frames.size());
        f.odometry_increment = m_pending_increment;
        f.observations = sf;
        m_seq.frames.push_back(std::move(f));
        m_pending_increment = mrpt::poses::CPose2D();
    }

    RawlogSequence& m_seq;
    std::string m_path;
    mrpt::poses::CPose2D m_pending_increment;
    std::optional<double> m_action_time;
    mrpt::obs::CSensoryFrame::Ptr m_pending_sf;
    std::optional<double> m_pending_time;
    std::size_t m_pending_entry = 0;
    std::optional<double> m_last_time;
    std::size_t m_last_entry = 0;
    std::optional<mrpt::poses::CPose2D> m_last_odometry, m_odometry_at_last_frame;
};

/// The innermost "Message:" line of a nested MRPT exception (the cause), else what().
std::string innermostMessage(const std::exception& e) {
    const std::string all = mrpt::exception_to_str(e);
    const auto pos = all.rfind("Message:");
    if (pos == std::string::npos) return e.what();  // not MRPT's: no "==== non-MRPT exception ====" banner
    const auto end = all.find('\n', pos);
    std::string m = all.substr(pos + 8, end == std::string::npos ? std::string::npos : end - pos - 8);
    return m.erase(0, m.find_first_not_of(' '));
}

/// True when no top-level entry starts after the entry at byte `entry_start` of the (uncompressed)
/// rawlog: the failed entry is the file's last one, i.e. a tail cut short while the file is being
/// written, not corruption in the middle. A sensory frame holds observations, so inside one only
/// another frame or action collection marks a later entry.
bool isLastEntry(const std::string& path, std::uint64_t entry_start) {
    mrpt::io::CFileGZInputStream in;
    if (!in.open(path)) return false;
    std::string bytes;
    std::vector<char> chunk(1 << 16);
    std::uint64_t skipped = 0;
    for (;;) {
        const size_t n = in.Read(chunk.data(), chunk.size());
        if (n == 0 || n > chunk.size()) break;  // end, or zlib's error (-1) as a huge size
        const std::uint64_t from = skipped >= entry_start ? 0 : std::min<std::uint64_t>(n, entry_start - skipped);
        bytes.append(chunk.data() + from, n - from);
        skipped += n;
    }
    static const std::string frame = std::string(1, '\x98') + "mrpt::obs::CSensoryFrame";
    static const std::string actions = std::string(1, '\x9c') + "mrpt::obs::CActionCollection";
    static const std::string observation = std::string(1, '\xa0') + "simp::obs::CObservationObjects3D";
    const bool in_frame = bytes.rfind(frame, 0) == 0;
    for (const auto* h : {&frame, &actions, &observation}) {
        if (in_frame && h == &observation) continue;
        if (bytes.find(*h, 1) != std::string::npos) return false;
    }
    return true;
}

void dispatch(FrameBuilder& builder, const mrpt::serialization::CSerializable::Ptr& obj) {
    if (auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj))
        builder.action(*acts);
    else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
        builder.sensoryFrame(sf);
    else if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj))
        builder.observation(obs);
    // no other class reaches here: readObjectGuarded(rawlogEntryClasses()) rejects it from its header
}

}  // namespace

RawlogSequence loadRawlogSequence(const std::string& path, RawlogTail tail) {
    if (!mrpt::system::fileExists(path)) throw std::runtime_error("rawlog '" + path + "' does not exist");
    obs::ReadableSize size;
    try {
        size = obs::readableFileSize(path);
    } catch (const std::exception& e) {
        throw std::runtime_error("rawlog " + std::string(e.what()));
    }
    mrpt::io::CFileGZInputStream in;
    if (!in.open(path)) throw std::runtime_error("rawlog '" + path + "' cannot be opened");
    // Through a BoundedArchive, as simp::obs::readRawlog: counts in the file are checked against the
    // bytes it still holds, and MRPT's own readers are guarded where they allocate what a file says.
    obs::BoundedArchive arch(in, size.bytes, path);
    arch.allowOnly(obs::rawlogClasses());  // other classes' MRPT readers trust the file's sizes

    RawlogSequence seq;
    FrameBuilder builder(seq, path);
    while (arch.bytesLeft() > 0) {  // a clean end lies between objects
        mrpt::serialization::CSerializable::Ptr obj;
        const std::uint64_t entry_start = arch.bytesRead();
        try {
            obj = arch.readObjectGuarded(obs::rawlogEntryClasses());
        } catch (const obs::UnreadClassError& e) {  // not corruption, and not a tail cut short
            throw std::runtime_error("rawlog '" + path + "': entry " + std::to_string(seq.entries) + ": " + e.what());
        } catch (const std::exception& e) {
            // A tail cut short (no entry after the failed one) of a file still being written.
            if (tail == RawlogTail::AllowTruncated && !seq.frames.empty() && !size.corrupt && isLastEntry(path, entry_start)) {
                seq.truncated_at_entry = seq.entries + 1;
                break;
            }
            const bool oom = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
            throw std::runtime_error("rawlog '" + path + "' is corrupt or truncated at entry " +
                                     std::to_string(seq.entries) + ": " +
                                     (oom ? std::string("an object claims more memory than available") : innermostMessage(e)));
        }
        if (!obj) throw std::runtime_error("rawlog '" + path + "' is corrupt at entry " + std::to_string(seq.entries) + ": null object");
        ++seq.entries;
        dispatch(builder, obj);
    }
    if (size.corrupt)  // the readable part ended between two entries: the rest is lost, say where
        throw std::runtime_error("rawlog '" + path + "' is corrupt after entry " + std::to_string(seq.entries) +
                                 ": the gzip data cannot be decompressed beyond " + std::to_string(size.bytes) + " bytes");
    builder.finish();
    if (seq.frames.empty()) throw std::runtime_error("rawlog '" + path + "' holds no sensory frame or observation");
    return seq;
}

}  // namespace simp::localization
