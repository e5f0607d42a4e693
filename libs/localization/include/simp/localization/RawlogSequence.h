#pragma once
/// \file RawlogSequence.h
/// A rawlog read as the filter consumes it: one entry per frame (the detections of all
/// cameras at one time) with the odometry increment since the previous frame.

#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace simp::localization {

struct SequenceFrame {
    double t_s = 0;                          ///< time (s): mrpt::Clock::toDouble of the frame's timestamp
    mrpt::poses::CPose2D odometry_increment; ///< motion since the previous frame, in the previous robot frame
    mrpt::obs::CSensoryFrame::Ptr observations;  ///< all observations of the frame (never null)
};

struct RawlogSequence {
    std::vector<SequenceFrame> frames;
    std::string format;                      ///< "actions+sensoryframes" or "observations"
    std::size_t entries = 0;                 ///< objects read from the file
    std::size_t truncated_at_entry = 0;      ///< > 0: entry index (1-based) of an incomplete last entry, not read
};

/// What loadRawlogSequence does with an entry cut short by the end of the file.
enum class RawlogTail {
    Strict,          ///< an error, like any corrupt entry
    AllowTruncated   ///< the complete entries before it are returned (a rawlog still being written)
};

/** Reads a .rawlog (plain or gz-compressed) in either MRPT format:
 *  - actions + sensory frames: the increments of all CActionRobotMovement2D before a
 *    CSensoryFrame are composed (raw odometry reading when present, else the PDF's mean);
 *  - observations only: consecutive observations with the same timestamp form a frame;
 *    the increment is the difference of the last CObservationOdometry readings.
 * The frame time is its first observation's timestamp (else the action's; else the frame
 * index, in seconds).
 * \throw std::runtime_error naming the file when it cannot be opened, is corrupt or truncated
 *        (with the entry index), holds no frame, or when a frame's time is not after the previous
 *        frame's (naming both entries: e.g. after `rawlog-edit --remap-timestamps`, which moves the
 *        observations but not the actions). With RawlogTail::AllowTruncated, an entry that
 *        fails to read where the file ends (no byte follows it) only ends the sequence.
 */
RawlogSequence loadRawlogSequence(const std::string& path, RawlogTail tail = RawlogTail::Strict);

}  // namespace simp::localization
