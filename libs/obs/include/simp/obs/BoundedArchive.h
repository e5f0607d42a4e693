#pragma once
/// \file BoundedArchive.h
/// An MRPT archive over an input stream of known length. Readers of untrusted files ask it how
/// many bytes are left before they size anything from a count or a length found in the file,
/// so a few bytes can never claim gigabytes (a count larger than the remaining bytes is an
/// error naming the entry, see ArchiveRead.h).

#include <mrpt/io/CStream.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/obs/HeaderScanner.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mrpt::rtti {
struct TRuntimeClassId;
}

namespace simp::obs {

class BoundedArchive : public mrpt::serialization::CArchive {
   public:
    /// `in` delivers exactly `size_bytes` more bytes (uncompressed); reading past them fails
    /// like an end of file. `description` names the source in MRPT's messages (the file name).
    BoundedArchive(mrpt::io::CStream& in, std::uint64_t size_bytes, std::string description);

    std::uint64_t bytesLeft() const { return m_size - bytesRead(); }
    std::uint64_t bytesRead() const { return m_fetched - (m_peeked.size() - m_peek_pos); }
    std::string getArchiveDescription() const override { return m_description; }

    /// Like CArchive::ReadObject(), but first checks the element counts that MRPT's own readers
    /// of CSensoryFrame and CActionCollection resize their vectors to (MRPT 2.5 allocates
    /// 16 bytes per claimed element before reading one: 64 GB from a 4-byte count) against the
    /// bytes left, and the motion models of the robot movements of an action collection (MRPT draws
    /// a Thrun model's particles, as many as the file says, while reading it).
    /// \throw std::invalid_argument naming the class and the count.
    mrpt::serialization::CSerializable::Ptr readObjectGuarded();

   protected:
    size_t write(const void* buf, size_t len) override;  ///< always throws: read only
    size_t read(void* buf, size_t len) override;

   private:
    /// Makes the next `n` bytes (fewer at the end) available without consuming them.
    const std::vector<std::uint8_t>& peek(std::size_t n);
    void guardCounts(const std::string& class_name, int version);
    /// The robot movements of an action collection about to be read: a Thrun motion model asking
    /// for more than 1e5 particles (MRPT would allocate them all) or an unknown model is an error.
    void guardMotionModels();
    /// Action collections and sensory frames nested inside the entry about to be read (MRPT reads
    /// them through its own ReadObject, sized from their counts, before checking their class):
    /// their counts are checked against the bytes left (64 KB ahead are looked at).
    void guardNestedCounts();
    /// readObjectGuarded() for an object that must derive from `base` (nullptr: any class), checked
    /// from its header before it is created; action collections are read here (MRPT 2.5's reader
    /// dereferences a non-CAction element unchecked). `depth`: nesting level (0: a file entry).
    mrpt::serialization::CSerializable::Ptr readGuarded(const mrpt::rtti::TRuntimeClassId* base, int depth);

    mrpt::io::CStream& m_in;
    std::uint64_t m_size;
    std::uint64_t m_fetched = 0;          ///< bytes taken from m_in
    std::vector<std::uint8_t> m_peeked;   ///< fetched, not yet delivered from m_peek_pos on
    std::size_t m_peek_pos = 0;
    std::string m_description;
    /// The headers the guards look for in the bytes ahead, each window scanned once.
    HeaderScanner m_movement_headers{"CActionRobotMovement2D"};
    HeaderScanner m_collection_headers{"CActionCollection"};
    HeaderScanner m_frame_headers{"CSensoryFrame"};
};

/// The bytes `archive` can still deliver when it knows them (a BoundedArchive); nullopt for
/// other archives (e.g. MRPT's tools reading through the plugin), whose readers then rely on
/// the fixed maxima of InputLimits.h alone.
std::optional<std::uint64_t> bytesLeftIn(const mrpt::serialization::CArchive& archive);

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
