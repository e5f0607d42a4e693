#pragma once
/// \file BoundedArchive.h
/// An MRPT archive over an input stream of known length. Readers of untrusted files ask it how
/// many bytes are left before they size anything from a count or a length found in the file,
/// so a few bytes can never claim gigabytes (a count larger than the remaining bytes is an
/// error naming the entry, see ArchiveRead.h).

#include <mrpt/io/CStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt::rtti {
struct TRuntimeClassId;
}

namespace simp::obs {

/// An object of a class the reader does not let MRPT read (BoundedArchive::allowOnly), found from its
/// header before MRPT created it; what() says which, where, and what the reader reads.
class UnreadClassError : public std::invalid_argument {
   public:
    UnreadClassError(const std::string& what, std::string cls) : std::invalid_argument(what), m_class(std::move(cls)) {}
    const std::string& className() const { return m_class; }

   private:
    std::string m_class;
};

class BoundedArchive : public mrpt::serialization::CArchive {
   public:
    /// `in` delivers exactly `size_bytes` more bytes (uncompressed); reading past them fails
    /// like an end of file. `description` names the source in MRPT's messages (the file name).
    BoundedArchive(mrpt::io::CStream& in, std::uint64_t size_bytes, std::string description);

    std::uint64_t bytesLeft() const { return m_size - bytesRead(); }
    std::uint64_t bytesRead() const { return m_fetched - (m_peeked.size() - m_peek_pos); }
    std::string getArchiveDescription() const override { return m_description; }

    /// Like CArchive::ReadObject(), with the guards below on every object the entry holds, however
    /// deeply nested, and nesting bounded (kMaxNestingStackBytes of stack: MRPT's readers recurse).
    /// `entry_bases` (if any): the entry must derive from one of them, checked from its header before
    /// MRPT creates and reads it (a rawlog entry is a frame, an action collection or an observation;
    /// libFuzzer: a 677-byte rawlog whose entry is an `mrpt::img::TCamera` with a camera-name length
    /// of 2^32-1 took 4.3 GB in MRPT's string reader).
    /// \throw std::invalid_argument naming the class, the field and where in the entry it is.
    mrpt::serialization::CSerializable::Ptr readObjectGuarded(
        const std::vector<const mrpt::rtti::TRuntimeClassId*>& entry_bases = {});

    /// From now on every object header MRPT reads, at any depth, must name one of `classes` (exactly,
    /// not a derived class), else readObjectGuarded() throws UnreadClassError before MRPT creates the
    /// object: MRPT's readers of other classes size strings and vectors from the file (a forged
    /// length: gigabytes), and MRPT's format stores no object length, so they cannot be skipped
    /// unread. Only `classes` that the guards of MrptClassGuards.cpp check or the project reads
    /// itself belong here (rawlogClasses()). Empty (the default): any class.
    void allowOnly(std::vector<const mrpt::rtti::TRuntimeClassId*> classes) { m_allowed = std::move(classes); }

   protected:
    size_t write(const void* buf, size_t len) override;  ///< always throws: read only
    /// Every byte MRPT reads passes here, at any nesting depth: this is where object headers are
    /// recognised (watch()) and the recursion depth is bounded.
    size_t read(void* buf, size_t len) override;

   private:
    /// Makes the next `n` bytes (fewer at the end) available without consuming them.
    const std::vector<std::uint8_t>& peek(std::size_t n);
    /// Called after each read: when the reads so far are MRPT's internal_ReadObjectHeader reading
    /// the name of an action collection, sensory frame or robot movement (read(1) of 0x80|length,
    /// then read(length); or the old format read(1), read(3) zeros, read(length)), onHeader()
    /// checks the object before MRPT creates it, wherever it is nested (issue #14: a header more
    /// than the 64 KB a scan ahead covered was not checked).
    void watch(const std::uint8_t* data, std::size_t len);
    /// MRPT 2.5 resizes a collection / frame to the count in the file (16 bytes per claimed
    /// element) and a Thrun motion model draws as many particles as the file says, all before
    /// anything is checked: counts against the bytes left (each alone, and all containers of the
    /// entry together, since nested ones claim the same bytes again), at most 64 actions per
    /// collection, at most 1e5 Thrun particles per entry, known motion models.
    /// Other classes: not allowed (allowOnly) is an error; else the checks of MrptClassGuards.h.
    void onHeader(const mrpt::rtti::TRuntimeClassId* id, bool old_format, std::size_t header_bytes);
    [[noreturn]] void fail(const std::string& what);
    /// fail() for a class not allowed, found `at` bytes into the entry.
    [[noreturn]] void failUnread(const std::string& name, std::uint64_t at);
    /// readObjectGuarded() for an object that must derive from one of `bases` (empty: any class), checked
    /// from its header before it is created; action collections and sensory frames are read here (MRPT
    /// 2.5's readers keep or dereference a null or wrong-class element unchecked). `depth`: nesting level (0: a file entry).
    mrpt::serialization::CSerializable::Ptr readGuarded(const std::vector<const mrpt::rtti::TRuntimeClassId*>& bases,
                                                        int depth);

    mrpt::io::CStream& m_in;
    std::uint64_t m_size;
    std::uint64_t m_fetched = 0;          ///< bytes taken from m_in
    std::vector<std::uint8_t> m_peeked;   ///< fetched, not yet delivered from m_peek_pos on
    std::size_t m_peek_pos = 0;
    std::string m_description;
    // The last two reads, for watch(): their sizes, the byte of a 1-byte read, whether a 3-byte one was zeros.
    std::size_t m_last_len = 0, m_prev_len = 0;
    std::uint8_t m_last_byte = 0, m_prev_byte = 0;
    bool m_last_zeros = false;
    // The entry being read (readObjectGuarded): where it starts, the bytes left then, what its
    // containers and motion models claimed so far, the first guard error (MRPT wraps exceptions
    // thrown inside its readers; this one is what the caller sees), the frame address of its start.
    std::uint64_t m_entry_start = 0, m_entry_left = 0, m_entry_elements = 0, m_entry_particles = 0;
    std::string m_guard_error;
    std::string m_guard_class;  ///< set when the first guard error is a class not allowed
    std::vector<const mrpt::rtti::TRuntimeClassId*> m_allowed;
    const char* m_stack_base = nullptr;
};

/// MRPT resolves a stored class name ignoring its namespace (findRegisteredClass's
/// allow_ignore_namespace, for pre-2.0 datasets): "x::CPose2D" and "CPose2D" both read as
/// mrpt::poses::CPose2D. A guard must match names the same way (a fuzzed "m,pt::obs::..." got past
/// an exact match and drew 19.7 million Thrun particles).
bool resolvesTo(const std::string& stored, const std::string& cls);

/// The bytes `archive` can still deliver when it knows them (a BoundedArchive); nullopt for
/// other archives (e.g. MRPT's tools reading through the plugin), whose readers then rely on
/// the fixed maxima of InputLimits.h alone.
std::optional<std::uint64_t> bytesLeftIn(const mrpt::serialization::CArchive& archive);

/// The classes a rawlog entry may have: CSensoryFrame, CActionCollection, CObservation (and derived).
const std::vector<const mrpt::rtti::TRuntimeClassId*>& rawlogEntryClasses();

/// The classes the project's rawlog readers let MRPT read, at any depth (BoundedArchive::allowOnly):
/// CSensoryFrame, CActionCollection, CActionRobotMovement2D, simp's CObservationObjects3D,
/// CObservation2DRangeScan, CObservationOdometry, CObservationComment, and inside them CPose2D, CPose3D,
/// CPosePDFGaussian(Inf), CMatrixF/D and TCamera; each with its sizes checked before MRPT reads it
/// (doc/formats.md "Limits"). Other observations (images, IMU, GPS, point clouds, ...) are refused.
const std::vector<const mrpt::rtti::TRuntimeClassId*>& rawlogClasses();

/// Uncompressed size (bytes) of a plain or gzip-compressed file: the file size, or for a gzip
/// file one streaming decompression pass (constant memory). \throw std::runtime_error naming
/// the file when it cannot be read.
std::uint64_t uncompressedFileSize(const std::string& path);

/// Like uncompressedFileSize(), but a corrupt gzip stream is not an error here: `bytes` is what
/// decompresses before the corruption and `corrupt` says the rest cannot be read (the caller then
/// names the entry where the readable data ends).
struct ReadableSize {
    std::uint64_t bytes = 0;
    bool corrupt = false;
};
ReadableSize readableFileSize(const std::string& path);

}  // namespace simp::obs
