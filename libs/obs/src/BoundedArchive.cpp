#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CAction.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/rtti/CObject.h>
#include <simp/obs/BoundedArchive.h>
#include <simp/obs/HeaderScanner.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace simp::obs {

BoundedArchive::BoundedArchive(mrpt::io::CStream& in, std::uint64_t size_bytes, std::string description)
    : m_in(in), m_size(size_bytes), m_description(std::move(description)) {}

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
        throw std::runtime_error("'" + m_description + "': the data ends in the middle of an object (" +
                                 std::to_string(len) + " bytes wanted, " + std::to_string(done) +
                                 " left; truncated or corrupted)");
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

/// Thrun's motion model draws this many particles at deserialization; MRPT's default is 300, and a
/// file cannot ask for more than this (MRPT 2.5 allocates 32 bytes per particle before any check).
constexpr std::uint32_t kMaxThrunParticles = 100000;
/// How far ahead of an action collection its robot movements are looked for (bytes), and how many
/// actions a collection may hold: a real one holds 1-3 actions of 100-400 bytes, so every robot
/// movement of an accepted collection lies inside the window.
constexpr std::size_t kActionScanBytes = 65536;
constexpr std::uint32_t kMaxActionsPerCollection = 64;

std::uint32_t u32At(const std::vector<std::uint8_t>& b, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, b.data() + at, 4);  // little endian, as MRPT writes on x86/arm
    return v;
}

/// The object header at `at` (MRPT 2.x: byte 0x80|length, then the name): its name, or nullopt if
/// `at` holds no new-format header within `b`.
std::optional<std::string> objectNameAt(const std::vector<std::uint8_t>& b, std::size_t at) {
    if (at >= b.size() || !(b[at] & 0x80)) return std::nullopt;
    const std::size_t len = b[at] & 0x7f;
    if (len == 0 || at + 1 + len > b.size()) return std::nullopt;
    return std::string(reinterpret_cast<const char*>(b.data() + at + 1), len);
}

/// Checks the motion model of a CActionRobotMovement2D whose data (after its version byte) starts
/// at `at` in `b` (MRPT 2.5, versions 4-7): u32 estimation method (1: a pose PDF object follows,
/// MRPT's reader segfaults on another class there); for odometry (0) a CPose2D object (header,
/// version 0: three floats, 1: three doubles, end flag), u32 model selection (0 Gaussian; MRPT
/// takes any other value as Thrun), six floats, u32 Thrun particle count. Returns the particles
/// MRPT will draw. A movement cut by the end of `b` is left to MRPT's reader (end of file).
std::uint64_t checkRobotMovement2D(const std::vector<std::uint8_t>& b, std::size_t at, const std::string& where) {
    if (at + 4 > b.size()) return 0;
    const std::uint32_t method = u32At(b, at);
    at += 4;
    if (method > 1)
        throw std::invalid_argument(where + ": CActionRobotMovement2D estimation method " + std::to_string(method) +
                                    " is neither 0 (odometry) nor 1 (scan matching) (corrupted file)");
    const auto name = objectNameAt(b, at);
    if (!name) {
        if (at < b.size() && at + 1 + (b[at] & 0x7f) <= b.size())
            throw std::invalid_argument(where + ": CActionRobotMovement2D: no object where its " +
                                        (method == 1 ? "pose PDF" : "odometry CPose2D") + " belongs (corrupted file)");
        return 0;
    }
    if (method == 1) {  // a pose PDF object follows; MRPT 2.5 crashes on any other object there
        const auto sep = name->rfind("::");
        if ((sep == std::string::npos ? *name : name->substr(sep + 2)).rfind("CPosePDF", 0) != 0)
            throw std::invalid_argument(where + ": CActionRobotMovement2D holds a '" + *name +
                                        "' where a pose PDF belongs (corrupted file)");
        return 0;
    }
    if (!resolvesTo(*name, "CPose2D"))
        throw std::invalid_argument(where + ": CActionRobotMovement2D holds a '" + *name +
                                    "' where its odometry CPose2D belongs (corrupted file)");
    at += 1 + name->size();
    if (at >= b.size()) return 0;
    const std::uint8_t pose_version = b[at];
    if (pose_version > 1)
        throw std::invalid_argument(where + ": CActionRobotMovement2D: odometry CPose2D version " +
                                    std::to_string(pose_version) + " is unknown (corrupted file)");
    at += 1 + (pose_version == 0 ? 12 : 24) + 1;  // version, x y phi, end flag
    if (at + 4 > b.size()) return 0;
    const std::uint32_t model = u32At(b, at);
    if (model > 1)
        throw std::invalid_argument(where + ": CActionRobotMovement2D motion model " + std::to_string(model) +
                                    " is neither 0 (Gaussian) nor 1 (Thrun) (corrupted file)");
    if (model == 0 || at + 4 + 24 + 4 > b.size()) return 0;
    const std::uint32_t particles = u32At(b, at + 4 + 24);
    if (particles > kMaxThrunParticles)
        throw std::invalid_argument(where + ": CActionRobotMovement2D asks for " + std::to_string(particles) +
                                    " Thrun motion-model particles (at most " + std::to_string(kMaxThrunParticles) +
                                    "; corrupted file)");
    return particles;
}

}  // namespace

void BoundedArchive::guardMotionModels() {
    // MRPT's CActionCollection reader deserializes its actions with MRPT's own reader, which a
    // robot movement asks to draw its Thrun particles: check every robot movement ahead first,
    // whatever namespace its stored name carries, and the particles of all of them together.
    const auto& b = peek(kActionScanBytes);
    if (b.size() >= 4 && u32At(b, 0) > kMaxActionsPerCollection)
        throw std::invalid_argument(m_description + ": CActionCollection holds " + std::to_string(u32At(b, 0)) +
                                    " actions (at most " + std::to_string(kMaxActionsPerCollection) +
                                    "; corrupted file)");
    std::uint64_t particles = 0;
    for (const auto& h : m_movement_headers.headersIn(b, bytesRead()))
        if (h.version >= 4 && h.version <= 7) particles += checkRobotMovement2D(b, h.data, m_description);
    if (particles > kMaxThrunParticles)
        throw std::invalid_argument(m_description + ": the robot movements of one CActionCollection ask for " +
                                    std::to_string(particles) + " Thrun motion-model particles together (at most " +
                                    std::to_string(kMaxThrunParticles) + "; corrupted file)");
}

void BoundedArchive::guardCounts(const std::string& class_name, int version) {
    // Offset of the u32 element count in the object's data (MRPT 2.5 serializeFrom).
    std::size_t offset = 0;
    if (class_name == "mrpt::obs::CActionCollection" && version == 0) offset = 0;
    else if (class_name == "mrpt::obs::CSensoryFrame" && version == 2) offset = 0;
    else if (class_name == "mrpt::obs::CSensoryFrame" && version == 1) offset = 4;  // + u32 ID
    else if (class_name == "mrpt::obs::CSensoryFrame" && version == 0) offset = 12;  // + ID, timestamp
    else return;
    const auto& bytes = peek(offset + 4);
    if (bytes.size() < offset + 4) return;  // truncated: MRPT's reader reports the end of file
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + offset, 4);  // little endian, as MRPT writes on x86/arm
    // Each element is an object: name length byte, >= 1 name byte, end flag.
    constexpr std::uint64_t kMinObjectBytes = 3;
    if (static_cast<std::uint64_t>(n) * kMinObjectBytes > bytesLeft() - (offset + 4))
        throw std::invalid_argument(class_name + ": element count " + std::to_string(n) + " needs at least " +
                                    std::to_string(n * kMinObjectBytes) + " bytes but only " +
                                    std::to_string(bytesLeft()) + " remain in the file (corrupted or truncated)");
}

void BoundedArchive::guardNestedCounts() {
    // MRPT reads the objects inside an entry with its own ReadObject, which no guard sees: an
    // action collection or sensory frame stored where an action or observation belongs is
    // deserialized (and sized from its count) before MRPT notices the wrong class. libFuzzer found
    // a 1 895-byte rawlog whose nested collection asked for 1.9e9 actions (30 GB). So every header
    // ahead that MRPT would read as one of them has its count checked: at most 64 actions, and the
    // elements of all of them together need 3 bytes each of what is left in the file (in a valid
    // file the containers' elements are disjoint, so they always fit; nested ones claim the same
    // bytes again). Headers further than the window ahead are checked when their entry is read.
    const auto& b = peek(kActionScanBytes);
    std::uint64_t elements = 0;
    const auto count = [&](const char* cls, std::size_t at) {
        if (at + 4 > b.size()) return;  // cut by the window or the end of file
        const std::uint32_t n = u32At(b, at);
        if (std::string(cls) == "CActionCollection" && n > kMaxActionsPerCollection)
            throw std::invalid_argument(m_description + ": a nested mrpt::obs::CActionCollection " +
                                        std::to_string(at) + " bytes into the entry holds " + std::to_string(n) +
                                        " actions (at most " + std::to_string(kMaxActionsPerCollection) +
                                        "; corrupted file)");
        elements += n;
        constexpr std::uint64_t kMinObjectBytes = 3;  // name length byte, >= 1 name byte, end flag
        if (elements * kMinObjectBytes > bytesLeft())
            throw std::invalid_argument(m_description + ": the " + cls + " " + std::to_string(at) +
                                        " bytes into the entry claims " + std::to_string(n) +
                                        " elements, more than the " + std::to_string(bytesLeft()) +
                                        " bytes left in the file can hold next to the containers before it "
                                        "(corrupted file)");
    };
    for (const auto& h : m_collection_headers.headersIn(b, bytesRead()))
        if (h.version == 0) count("CActionCollection", h.data);
    for (const auto& h : m_frame_headers.headersIn(b, bytesRead()))
        if (h.version <= 2) count("CSensoryFrame", h.data + (h.version == 2 ? 0 : h.version == 1 ? 4 : 12));
}

mrpt::serialization::CSerializable::Ptr BoundedArchive::readObjectGuarded() { return readGuarded(nullptr, 0); }

mrpt::serialization::CSerializable::Ptr BoundedArchive::readGuarded(const mrpt::rtti::TRuntimeClassId* base, int depth) {
    std::string class_name;
    bool old_format = false;
    int8_t version = -1;
    internal_ReadObjectHeader(class_name, old_format, version);
    if (base && class_name == "nullptr")
        throw std::invalid_argument(m_description + ": a null object where a " + base->className +
                                    " belongs (corrupted file)");
    mrpt::serialization::CSerializable::Ptr obj;
    if (class_name != "nullptr") {
        const auto* id = mrpt::rtti::findRegisteredClass(class_name);
        if (!id) throw std::runtime_error("Stored object has class '" + class_name + "' which is not registered!");
        if (base && !id->derivedFrom(base))
            throw std::invalid_argument(m_description + ": a '" + class_name + "' where a " + base->className +
                                        " belongs (corrupted file)");
        const std::string cls = id->className;
        guardCounts(cls, static_cast<std::uint8_t>(version));
        if (cls == "mrpt::obs::CActionCollection") guardMotionModels();
        // A robot movement stored as an entry of its own (not in a collection) reaches MRPT's
        // reader the same way (libFuzzer: the null pose PDF segfault past the collection guard).
        if (cls == "mrpt::obs::CActionRobotMovement2D" && version >= 4 && version <= 7)
            checkRobotMovement2D(peek(kActionScanBytes), 0, m_description);
        if (depth == 0) guardNestedCounts();
        obj = mrpt::ptr_cast<mrpt::serialization::CSerializable>::from(id->createObject());
        if (cls == "mrpt::obs::CActionCollection" && version == 0) {
            // Read here, not by MRPT 2.5's CActionCollection::serializeFrom: that one casts each
            // stored object to CAction and dereferences the result unchecked, so a null object or
            // any other class there (libFuzzer: a CPose2D) is a segfault. Each action's class is
            // checked from its header before it is created.
            auto& actions = dynamic_cast<mrpt::obs::CActionCollection&>(*obj);
            const auto n = ReadAs<std::uint32_t>();  // bounded by guardCounts / guardMotionModels
            for (std::uint32_t i = 0; i < n; ++i) {
                const auto a = std::dynamic_pointer_cast<mrpt::obs::CAction>(
                    readGuarded(&mrpt::obs::CAction::GetRuntimeClassIdStatic(), depth + 1));
                actions.insertPtr(a);
            }
            if (!old_format && ReadAs<std::uint8_t>() != 0x88)  // MRPT's SERIALIZATION_END_FLAG
                throw std::invalid_argument(m_description + ": CActionCollection: end flag missing (corrupted file)");
            return obj;
        }
    }
    internal_ReadObject(obj.get(), class_name, old_format, version);
    return obj;
}

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
