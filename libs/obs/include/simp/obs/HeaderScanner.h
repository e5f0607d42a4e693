#pragma once
/// \file HeaderScanner.h
/// Where MRPT's archive reader would find object headers of one class in the bytes ahead of a
/// rawlog entry (BoundedArchive's guards check them before MRPT sizes anything from them).

#include <cstdint>
#include <string>
#include <vector>

namespace simp::obs {

/// MRPT resolves a stored class name ignoring its namespace (findRegisteredClass's
/// allow_ignore_namespace, for pre-2.0 datasets): "x::CPose2D" and "CPose2D" both read as
/// mrpt::poses::CPose2D. A guard must match names the same way (a fuzzed "m,pt::obs::..." got past
/// an exact match and drew 19.7 million Thrun particles).
bool resolvesTo(const std::string& stored, const std::string& cls);

/// An object header found in a window: where its prefix (length byte(s)) starts, where the
/// object's data starts (after its version), and its version; offsets relative to the window.
struct HeaderAt {
    std::size_t prefix;
    std::size_t data;
    std::uint32_t version;
};

/// Every position of the window `b[0, n)` that MRPT 2.5's CArchive::internal_ReadObjectHeader would
/// read as a header of class `cls`: new format (byte 0x80|length, name, int8 version) or old format
/// (length, 0 0 0, name, int32 version); MRPT copies the name as a C string, so a NUL inside the
/// declared length ends it ("mrpt::obs::CActionCollection\0\1\0\0" with length 33 is a collection),
/// and findRegisteredClass ignores the namespace (resolvesTo). libFuzzer found both ways past a
/// match of the exact name. Ordered by prefix position.
std::vector<HeaderAt> headersOf(const std::uint8_t* b, std::size_t n, const std::string& cls);

/// headersOf() over the windows a reader peeks, one after the other: each window starts where
/// the reader is (never before the previous one) and ends a fixed distance ahead, so consecutive
/// windows share all but one entry. The bytes are scanned once, not once per entry (a one-hour
/// rawlog: 25 s of a 68 s run went to scanning the same 64 KB again for every entry).
class HeaderScanner {
   public:
    explicit HeaderScanner(std::string cls) : m_cls(std::move(cls)) {}
    /// Exactly headersOf(b.data(), b.size(), cls) for the window `b` starting at absolute offset `base`.
    std::vector<HeaderAt> headersIn(const std::vector<std::uint8_t>& b, std::uint64_t base);

   private:
    struct Found {
        std::uint64_t prefix, data;  ///< absolute offsets
        std::uint32_t version;
    };
    std::string m_cls;
    std::uint64_t m_begin = 0, m_end = 0;  ///< the last window scanned, absolute
    std::vector<Found> m_found;            ///< headers in it, by prefix
};

}  // namespace simp::obs
