#include <simp/obs/HeaderScanner.h>

#include <algorithm>
#include <cstring>
#include <string_view>

namespace simp::obs {
namespace {

constexpr std::size_t kMaxNameLength = 120;  // MRPT rejects longer names
/// A header whose prefix starts this far before the end of a window lies wholly inside it (prefix
/// <= 4 bytes, name <= 120, version <= 4, the byte after the name): found there or never.
constexpr std::uint64_t kHeaderSpan = 4 + kMaxNameLength + 4 + 1;

}  // namespace

bool resolvesTo(const std::string& stored, const std::string& cls) {
    const auto sep = stored.rfind("::");
    return (sep == std::string::npos ? stored : stored.substr(sep + 2)) == cls;
}

std::vector<HeaderAt> headersOf(const std::uint8_t* b, std::size_t n, const std::string& cls) {
    std::vector<HeaderAt> out;
    const std::string_view all(reinterpret_cast<const char*>(b), n);
    for (auto pos = all.find(cls); pos != std::string_view::npos; pos = all.find(cls, pos + 1)) {
        const std::size_t e = pos + cls.size();  // where the resolved name ends
        for (std::size_t l = cls.size(); l <= kMaxNameLength && l <= e; ++l) {
            const std::size_t s = e - l;  // where the name starts
            if (b[s] == 0) break;         // the name would end before `e`, and so for longer ones
            if (!resolvesTo(std::string(all.substr(s, l)), cls)) continue;
            const auto declared_ok = [&](std::size_t len) {
                return len >= l && len <= kMaxNameLength && (len == l || (e < n && b[e] == 0));
            };
            if (s >= 1 && (b[s - 1] & 0x80) && declared_ok(b[s - 1] & 0x7fu) && s + (b[s - 1] & 0x7fu) < n) {
                const std::size_t v = s + (b[s - 1] & 0x7fu);
                out.push_back({s - 1, v + 1, b[v]});
            }
            if (s >= 4 && !(b[s - 4] & 0x80) && b[s - 3] == 0 && b[s - 2] == 0 && b[s - 1] == 0 && declared_ok(b[s - 4]) &&
                s + b[s - 4] + 4 <= n) {
                const std::size_t v = s + b[s - 4];
                std::uint32_t version = 0;
                std::memcpy(&version, b + v, 4);  // little endian, as MRPT writes on x86/arm
                out.push_back({s - 4, v + 4, version});
            }
        }
    }
    return out;
}

std::vector<HeaderAt> HeaderScanner::headersIn(const std::vector<std::uint8_t>& b, std::uint64_t base) {
    const std::uint64_t end = base + b.size();
    // Rescan from where a header could have been cut by the last window's end; a window that does
    // not continue the last one is scanned whole.
    std::uint64_t from = base;
    if (base >= m_begin && base <= m_end && end >= m_end && m_end >= base + kHeaderSpan) from = m_end - kHeaderSpan;
    m_found.erase(std::remove_if(m_found.begin(), m_found.end(),
                                 [&](const Found& f) { return f.prefix < base || f.prefix >= from || from == base; }),
                  m_found.end());
    for (const auto& h : headersOf(b.data() + (from - base), static_cast<std::size_t>(end - from), m_cls))
        m_found.push_back({from + h.prefix, from + h.data, h.version});
    m_begin = base;
    m_end = end;
    std::vector<HeaderAt> out;
    out.reserve(m_found.size());
    for (const auto& f : m_found)
        out.push_back({static_cast<std::size_t>(f.prefix - base), static_cast<std::size_t>(f.data - base), f.version});
    return out;
}

}  // namespace simp::obs
