#pragma once
/// \file ArchiveRead.h
/// Checked reading of untrusted binary archives: every count or length is compared with a
/// documented maximum and with the bytes the archive can still deliver (BoundedArchive)
/// *before* anything is allocated, and every bool byte must be 0 or 1 (loading another byte
/// into a `bool` is undefined behaviour). The wire format is MRPT's own (a u32 length prefix
/// for strings and string lists), so files stay readable by both.
/// Errors are std::invalid_argument naming `what` (the entry and field) and the value.

#include <mrpt/img/TCamera.h>
#include <mrpt/serialization/CArchive.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace simp::obs::archive {

/// A bool stored as one byte; any value other than 0 or 1 is an error.
bool readBool(mrpt::serialization::CArchive& in, const std::string& what);

/// A u32 count of items that take at least `min_bytes_each` bytes each in the archive:
/// rejected above `max_count` or when count * min_bytes_each exceeds the bytes left.
std::uint32_t readCount(mrpt::serialization::CArchive& in, std::size_t min_bytes_each, std::size_t max_count,
                        const std::string& what);

/// A string in MRPT's format (u32 length, bytes), at most `max_length` bytes.
std::string readString(mrpt::serialization::CArchive& in, std::size_t max_length, const std::string& what);

/// A std::vector<std::string> in MRPT's format (u32 count, then strings).
std::vector<std::string> readStringList(mrpt::serialization::CArchive& in, std::size_t max_count,
                                        std::size_t max_length, const std::string& what);

/// A double that must be finite and within [lo, hi].
double readDouble(mrpt::serialization::CArchive& in, double lo, double hi, const std::string& what);

/// An mrpt::img::TCamera object as MRPT writes it (`out << camera`: object header, version
/// 4..6, fields, end flag), read field by field so that its camera name's length is checked
/// and its distortion enum byte validated; versions 0..3 (MRPT < 1.5) are rejected.
mrpt::img::TCamera readCamera(mrpt::serialization::CArchive& in, const std::string& what);

}  // namespace simp::obs::archive
