#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CAction.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/rtti/CObject.h>
#include <simp/obs/InputLimits.h>
#include <simp/obs/BoundedArchive.h>

#include "MrptClassGuards.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace simp::obs {

namespace {

using limits::kMaxThrunParticles;
/// A real collection holds 1-3 actions.
constexpr std::uint32_t kMaxActionsPerCollection = 64;
/// Each element of a container is an object: name length byte, >= 1 name byte, end flag.
constexpr std::uint64_t kMinObjectBytes = 3;
/// Stack MRPT's recursive readers may use below the start of an entry: a valid entry nests 3-4
/// objects deep (a few KB); 8 MB is a thread's whole stack on Linux.
constexpr std::size_t kMaxNestingStackBytes = 512 * 1024;

std::string shortName(const std::string& name) {
    const auto sep = name.rfind("::");
    return sep == std::string::npos ? name : name.substr(sep + 2);
}

}  // namespace

bool resolvesTo(const std::string& stored, const std::string& cls) { return shortName(stored) == cls; }

BoundedArchive::BoundedArchive(mrpt::io::CStream& in, std::uint64_t size_bytes, std::string description)
    : m_in(in), m_size(size_bytes), m_description(std::move(description)), m_entry_left(size_bytes) {}

size_t BoundedArchive::write(const void*, size_t) {
    throw std::logic_error("BoundedArchive '" + m_description + "': is read only");
}

size_t BoundedArchive::read(void* buf, size_t len) {
    auto* out = static_cast<std::uint8_t*>(buf);
    size_t done = 0;
    if (m_peek_pos < m_peeked.size()) {  // bytes a peek already fetched come first
        done = std::min(len, m_peeked.size() - m_peek_pos);
        std::memcpy(out, m_peeked.data() + m_peek_pos, done);
        m_peek_pos += done;
        if (m_peek_pos == m_peeked.size()) {
            m_peeked.clear();
            m_peek_pos = 0;
        }
    }
    const auto n = static_cast<size_t>(std::min<std::uint64_t>(len - done, m_size - m_fetched));
    if (n > 0) {
        const size_t got = m_in.Read(out + done, n);
        m_fetched += got;
        done += got;
    }
    // MRPT 2.5's ReadBuffer only fails when nothing at all is read: a u32 count cut by the end of
    // the file was taken with its missing bytes uninitialized (libFuzzer: a 32-byte rawlog whose
    // collection count was cut after 2 bytes allocated > 1 GB). Every read of an archive is of a
    // fixed size, so a short one is the end of the data in the middle of an object.
    if (done < len)
        fail("'" + m_description + "': the data ends in the middle of an object (" + std::to_string(len) +
             " bytes wanted, " + std::to_string(done) + " left; truncated or corrupted)");
    // MRPT's readers recurse into nested objects (a sensory frame where an observation belongs is
    // read whole); thousands of nested levels cost a few bytes each and would overflow the stack.
    const auto* here = static_cast<const char*>(__builtin_frame_address(0));
    if (m_stack_base && m_stack_base > here && static_cast<std::size_t>(m_stack_base - here) > kMaxNestingStackBytes)
        fail(m_description + ": objects nested too deeply " + std::to_string(bytesRead() - m_entry_start) +
             " bytes into the entry (more than " + std::to_string(kMaxNestingStackBytes / 1024) +
             " KB of stack for MRPT's recursive readers; corrupted file)");
    watch(out, done);
    return done;
}

const std::vector<std::uint8_t>& BoundedArchive::peek(std::size_t n) {
    if (m_peek_pos > 0) {
        m_peeked.erase(m_peeked.begin(), m_peeked.begin() + static_cast<std::ptrdiff_t>(m_peek_pos));
        m_peek_pos = 0;
    }
    while (m_peeked.size() < n && m_fetched < m_size) {
        const auto want = static_cast<size_t>(std::min<std::uint64_t>(n - m_peeked.size(), m_size - m_fetched));
        const auto old = m_peeked.size();
        m_peeked.resize(old + want);
        const size_t got = m_in.Read(m_peeked.data() + old, want);
        m_peeked.resize(old + got);
        m_fetched += got;
        if (got == 0) break;
    }
    return m_peeked;
}


namespace {

/// What fail() throws. MRPT's readers catch every exception at each nesting level and rethrow it
/// wrapped with a backtrace (internal_ReadObject, MRPT_END), except std::bad_alloc, which passes
/// unchanged: a guard error from 1 000 levels deep took 105 s to surface that way. It is turned
/// into std::invalid_argument with the same message by readObjectGuarded().
struct GuardAbort : std::bad_alloc {
    const char* what() const noexcept override { return "simp::obs::BoundedArchive guard (see its message)"; }
};

}  // namespace

void BoundedArchive::fail(const std::string& what) {
    if (!m_stack_base) throw std::invalid_argument(what);  // not inside readObjectGuarded()
    if (m_guard_error.empty()) m_guard_error = what;
    throw GuardAbort();
}

void BoundedArchive::failUnread(const std::string& name, std::uint64_t at) {
    if (m_guard_error.empty()) m_guard_class = name;
    fail("class " + name + " (" + std::to_string(at) + " bytes into the entry) is not read by simp: its MRPT reader " +
         "would trust the sizes in the file, and an object's length is not stored, so it cannot be skipped " +
         "(simp reads " + detail::rawlogClassesText() + "; to drop other sensors' observations see doc/bad-input.md, " +
         "rawlog-edit --keep-label / --remove-label)");
}

void BoundedArchive::watch(const std::uint8_t* data, std::size_t len) {
    static constexpr std::size_t kLongest = 120;  // MRPT's maximum name length
    if (len >= 1 && len <= kLongest) {
        const bool new_format = m_last_len == 1 && (m_last_byte & 0x80) && (m_last_byte & 0x7fu) == len;
        const bool old_format = m_last_len == 3 && m_last_zeros && m_prev_len == 1 && m_prev_byte == len;
        if (new_format || old_format) {
            // MRPT copies the name as a C string (a NUL inside the declared length ends it) and resolves
            // it ignoring the namespace; the same lookup here. Data that merely looks like a header
            // names no registered class (or it is a forged header, and rejecting it is right).
            const auto* c = reinterpret_cast<const char*>(data);
            const std::string name(c, ::strnlen(c, len));
            if (const auto* id = mrpt::rtti::findRegisteredClass(name))
                onHeader(id, old_format, len + (old_format ? 4 : 1));
        }
    }
    m_prev_len = m_last_len;
    m_prev_byte = m_last_byte;
    m_last_len = len;
    m_last_byte = len > 0 ? data[0] : 0;
    m_last_zeros = len == 3 && data[0] == 0 && data[1] == 0 && data[2] == 0;
}

void BoundedArchive::onHeader(const mrpt::rtti::TRuntimeClassId* id, bool old_format, std::size_t header_bytes) {
    // Called as MRPT has just read the class name: the version and the object's data follow.
    const std::uint64_t at = bytesRead() - header_bytes - m_entry_start;
    if (!m_allowed.empty() && std::find(m_allowed.begin(), m_allowed.end(), id) == m_allowed.end())
        failUnread(id->className, at);
    const std::string cls = shortName(id->className);
    const std::string where = m_description + ": the " + cls + " " + std::to_string(at) + " bytes into the entry";
    const std::size_t vbytes = old_format ? 4 : 1;
    const bool container = id == CLASS_ID(mrpt::obs::CActionCollection) || id == CLASS_ID(mrpt::obs::CSensoryFrame);
    if (!container) {
        detail::Ahead ahead{[this](std::size_t n) -> const std::vector<std::uint8_t>& { return peek(n); }, bytesLeft(),
                            vbytes};
        try {
            m_entry_particles += detail::checkObject(id, ahead, where);
        } catch (const std::invalid_argument& e) {
            fail(e.what());
        }
        if (m_entry_particles > kMaxThrunParticles)
            fail(where + ": the robot movements of one entry ask for " + std::to_string(m_entry_particles) +
                 " Thrun motion-model particles together (at most " + std::to_string(kMaxThrunParticles) +
                 "; corrupted file)");
        return;
    }
    const auto& b = peek(vbytes + 12 + 4);
    if (b.size() < vbytes) return;  // cut by the end of the file: MRPT's reader says so
    const std::uint32_t version = old_format ? detail::u32At(b, 0) : b[0];
    // Offset of the u32 element count in the object's data (MRPT 2.5 serializeFrom).
    std::size_t offset = 0;
    if (cls == "CActionCollection" && version == 0) offset = 0;
    else if (cls == "CSensoryFrame" && version <= 2) offset = version == 2 ? 0 : version == 1 ? 4 : 12;  // ID, time
    else return;
    if (b.size() < vbytes + offset + 4) return;  // truncated: MRPT's reader reports the end of file
    const std::uint32_t n = detail::u32At(b, vbytes + offset);
    const std::uint64_t left = bytesLeft() - (vbytes + offset + 4);
    if (n * kMinObjectBytes > left)
        fail(where + ": element count " + std::to_string(n) + " needs at least " +
             std::to_string(n * kMinObjectBytes) + " bytes but only " + std::to_string(left) +
             " remain in the file (corrupted or truncated)");
    if (cls == "CActionCollection" && n > kMaxActionsPerCollection)
        fail(where + " holds " + std::to_string(n) + " actions (at most " + std::to_string(kMaxActionsPerCollection) +
             "; corrupted file)");
    // In a valid entry the containers' elements are distinct objects, so all of them together fit
    // in the entry's bytes; nested containers claim the same bytes again (a 1.9e9-action collection
    // inside a collection: 30 GB from 1 895 bytes, found by libFuzzer).
    m_entry_elements += n;
    if (m_entry_elements * kMinObjectBytes > m_entry_left)
        fail(where + " claims " + std::to_string(n) + " elements: with those of the containers before it " +
             std::to_string(m_entry_elements) + ", more than the " + std::to_string(m_entry_left) +
             " bytes left in the file at the entry's start can hold (nested containers; corrupted file)");
}

mrpt::serialization::CSerializable::Ptr BoundedArchive::readObjectGuarded(
    const std::vector<const mrpt::rtti::TRuntimeClassId*>& entry_bases) {
    m_entry_start = bytesRead();
    m_entry_left = bytesLeft();
    m_entry_elements = m_entry_particles = 0;
    m_guard_error.clear();
    m_guard_class.clear();
    m_stack_base = static_cast<const char*>(__builtin_frame_address(0));
    struct Reset {  // the depth check applies below this call only
        const char*& p;
        ~Reset() { p = nullptr; }
    } reset{m_stack_base};
    try {
        return readGuarded(entry_bases, 0);
    } catch (const std::exception&) {  // GuardAbort, or MRPT's wrapping of an earlier guard error
        if (!m_guard_class.empty()) throw UnreadClassError(m_guard_error, m_guard_class);
        if (!m_guard_error.empty()) throw std::invalid_argument(m_guard_error);
        throw;
    }
}

mrpt::serialization::CSerializable::Ptr BoundedArchive::readGuarded(
    const std::vector<const mrpt::rtti::TRuntimeClassId*>& bases, int depth) {
    std::string class_name;
    bool old_format = false;
    int8_t version = -1;
    internal_ReadObjectHeader(class_name, old_format, version);  // watch() checks guarded classes
    std::string wanted;  // "a X or a Y", for the messages
    for (const auto* b : bases) wanted += (wanted.empty() ? "a " : " or a ") + std::string(b->className);
    if (!bases.empty() && class_name == "nullptr")
        throw std::invalid_argument(m_description + ": a null object where " + wanted + " belongs (corrupted file)");
    mrpt::serialization::CSerializable::Ptr obj;
    if (class_name != "nullptr") {
        const auto* id = mrpt::rtti::findRegisteredClass(class_name);
        if (!id) throw std::runtime_error("Stored object has class '" + class_name + "' which is not registered!");
        if (!bases.empty() && std::none_of(bases.begin(), bases.end(), [&](auto* b) { return id->derivedFrom(b); }))
            throw std::invalid_argument(m_description + ": a '" + class_name + "' where " + wanted +
                                        " belongs (corrupted file)");
        obj = mrpt::ptr_cast<mrpt::serialization::CSerializable>::from(id->createObject());
        if (std::string(id->className) == "mrpt::obs::CActionCollection" && version == 0) {
            // Read here, not by MRPT 2.5's CActionCollection::serializeFrom: that one casts each
            // stored object to CAction and dereferences the result unchecked, so a null object or
            // any other class there (libFuzzer: a CPose2D) is a segfault. Each action's class is
            // checked from its header before it is created.
            auto& actions = dynamic_cast<mrpt::obs::CActionCollection&>(*obj);
            const auto n = ReadAs<std::uint32_t>();  // bounded by onHeader()
            for (std::uint32_t i = 0; i < n; ++i) {
                const auto a = std::dynamic_pointer_cast<mrpt::obs::CAction>(
                    readGuarded({&mrpt::obs::CAction::GetRuntimeClassIdStatic()}, depth + 1));
                actions.insertPtr(a);
            }
            if (!old_format && ReadAs<std::uint8_t>() != 0x88)  // MRPT's SERIALIZATION_END_FLAG
                throw std::invalid_argument(m_description + ": CActionCollection: end flag missing (corrupted file)");
            return obj;
        }
        if (std::string(id->className) == "mrpt::obs::CSensoryFrame" && version >= 0 && version <= 2) {
            // Read here, not by MRPT 2.5's CSensoryFrame::serializeFrom: that one stores whatever object an
            // element is (a null one, or another class cast to a null observation) and, in version 0,
            // dereferences each to set its time stamp (a segfault); the readers dereference them too.
            // Each element must be an observation, checked from its header before it is created.
            auto& frame = dynamic_cast<mrpt::obs::CSensoryFrame&>(*obj);
            if (version < 2) (void)ReadAs<std::uint32_t>();  // ID, removed in version 2
            std::optional<mrpt::Clock::time_point> t;
            if (version == 0) t = mrpt::Clock::time_point(mrpt::Clock::duration(ReadAs<std::uint64_t>()));
            const auto n = ReadAs<std::uint32_t>();  // bounded by onHeader()
            for (std::uint32_t i = 0; i < n; ++i) {
                const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(
                    readGuarded({&mrpt::obs::CObservation::GetRuntimeClassIdStatic()}, depth + 1));
                if (t) o->timestamp = *t;
                frame.insert(o);
            }
            if (!old_format && ReadAs<std::uint8_t>() != 0x88)
                throw std::invalid_argument(m_description + ": CSensoryFrame: end flag missing (corrupted file)");
            return obj;
        }
    }
    internal_ReadObject(obj.get(), class_name, old_format, version);
    return obj;
}

const std::vector<const mrpt::rtti::TRuntimeClassId*>& rawlogEntryClasses() {
    static const std::vector<const mrpt::rtti::TRuntimeClassId*> classes{
        &mrpt::obs::CSensoryFrame::GetRuntimeClassIdStatic(), &mrpt::obs::CActionCollection::GetRuntimeClassIdStatic(),
        &mrpt::obs::CObservation::GetRuntimeClassIdStatic()};
    return classes;
}

const std::vector<const mrpt::rtti::TRuntimeClassId*>& rawlogClasses() { return detail::guardedRawlogClasses(); }

std::optional<std::uint64_t> bytesLeftIn(const mrpt::serialization::CArchive& archive) {
    if (const auto* b = dynamic_cast<const BoundedArchive*>(&archive)) return b->bytesLeft();
    return std::nullopt;
}

ReadableSize readableFileSize(const std::string& path) {
    std::error_code ec;
    const auto file_size = std::filesystem::file_size(path, ec);
    if (ec) throw std::runtime_error("'" + path + "': cannot get the file size: " + ec.message());
    unsigned char magic[2] = {0, 0};
    {
        std::ifstream f(path, std::ios::binary);
        if (!f) throw std::runtime_error("'" + path + "': cannot open for reading");
        f.read(reinterpret_cast<char*>(magic), 2);
    }
    if (!(magic[0] == 0x1f && magic[1] == 0x8b)) return {file_size, false};  // not gzip
    // gzip's own size field (ISIZE) is modulo 2^32 and per member: count the bytes instead.
    mrpt::io::CFileGZInputStream gz;
    if (!gz.open(path)) throw std::runtime_error("'" + path + "': cannot open for reading");
    std::vector<unsigned char> chunk(1 << 16);
    ReadableSize r;
    for (;;) {
        const size_t n = gz.Read(chunk.data(), chunk.size());
        if (n == 0) break;
        if (n > chunk.size()) {  // zlib's error (-1) arrives as a huge size
            r.corrupt = true;
            break;
        }
        r.bytes += n;
    }
    return r;
}

std::uint64_t uncompressedFileSize(const std::string& path) {
    const ReadableSize r = readableFileSize(path);
    if (r.corrupt) throw std::runtime_error("'" + path + "': corrupt gzip data after " + std::to_string(r.bytes) + " bytes");
    return r.bytes;
}

}  // namespace simp::obs
