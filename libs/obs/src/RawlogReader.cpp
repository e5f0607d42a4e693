#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/obs/BoundedArchive.h>
#include <simp/obs/RawlogReader.h>

#include <filesystem>
#include <stdexcept>

namespace simp::obs {
namespace {

struct Reader {
    std::string path;
    std::vector<RawlogFrame> frames;
    std::optional<mrpt::math::TPose2D> pending_increment;  // from an action, for the next frame
    std::optional<mrpt::poses::CPose2D> last_odometry;     // observation-only format

    [[noreturn]] void fail(std::size_t entry, const std::string& what) const {
        throw std::runtime_error("rawlog '" + path + "': entry " + std::to_string(entry) + ": " + what);
    }

    void addIncrement(const mrpt::math::TPose2D& inc) {
        if (pending_increment)
            pending_increment = (mrpt::poses::CPose2D(*pending_increment) + mrpt::poses::CPose2D(inc)).asTPose();
        else
            pending_increment = inc;
    }

    void addObservation(const CObservationObjects3D::Ptr& o) {
        if (frames.empty() || frames.back().timestamp != o->timestamp || pending_increment) {
            RawlogFrame f;
            f.timestamp = o->timestamp;
            f.odometry_increment = pending_increment;
            pending_increment.reset();
            frames.push_back(std::move(f));
        }
        frames.back().observations.push_back(o);
    }

    void handle(const mrpt::serialization::CSerializable::Ptr& obj, std::size_t entry) {
        if (auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj)) {
            if (auto mv = acts->getBestMovementEstimation()) addIncrement(mv->poseChange->getMeanVal().asTPose());
        } else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj)) {
            RawlogFrame f;
            f.odometry_increment = pending_increment;
            pending_increment.reset();
            for (const auto& o : *sf)
                if (auto det = std::dynamic_pointer_cast<CObservationObjects3D>(o)) {
                    if (f.observations.empty()) f.timestamp = det->timestamp;
                    f.observations.push_back(det);
                }
            if (!f.observations.empty() || f.odometry_increment) frames.push_back(std::move(f));
        } else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obj)) {
            if (last_odometry) addIncrement((odo->odometry - *last_odometry).asTPose());
            last_odometry = odo->odometry;
        } else if (auto det = std::dynamic_pointer_cast<CObservationObjects3D>(obj)) {
            addObservation(det);
        } else if (!std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) {
            fail(entry, std::string("unexpected object of class ") + obj->GetRuntimeClass()->className);
        }
    }
};

}  // namespace

std::vector<RawlogFrame> readRawlog(const std::string& path) {
    if (!std::filesystem::is_regular_file(path))
        throw std::runtime_error("rawlog '" + path + "': file does not exist");
    std::uint64_t size = 0;
    try {
        size = uncompressedFileSize(path);
    } catch (const std::exception& e) {
        throw std::runtime_error("rawlog " + std::string(e.what()));
    }
    mrpt::io::CFileGZInputStream file;
    if (!file.open(path)) throw std::runtime_error("rawlog '" + path + "': cannot open");
    return readRawlog(file, size, path);
}

std::vector<RawlogFrame> readRawlog(mrpt::io::CStream& in, std::uint64_t size_bytes, const std::string& name) {
    // Every object is read through a BoundedArchive: our readers and the guards for MRPT's
    // vector-sizing readers compare the counts in the file with the bytes it still holds.
    BoundedArchive archive(in, size_bytes, name);
    archive.allowOnly(rawlogClasses());  // other classes' MRPT readers trust the file's sizes
    Reader r;
    r.path = name;
    for (std::size_t entry = 0;; ++entry) {
        if (archive.bytesLeft() == 0) break;  // clean end between objects
        mrpt::serialization::CSerializable::Ptr obj;
        try {
            obj = archive.readObjectGuarded(rawlogEntryClasses());
        } catch (const UnreadClassError& e) {
            r.fail(entry, e.what());
        } catch (const mrpt::serialization::CExceptionEOF& e) {
            r.fail(entry, std::string("file ends in the middle of an object (truncated): ") + e.what());
        } catch (const std::bad_alloc&) {
            r.fail(entry, "corrupted object: it claims more memory than available");
        } catch (const std::exception& e) {
            if (archive.bytesLeft() == 0)
                r.fail(entry, std::string("file ends in the middle of an object (truncated): ") + e.what());
            r.fail(entry, std::string("corrupted or unreadable object: ") + e.what());
        }
        if (!obj) r.fail(entry, "null object");
        r.handle(obj, entry);
    }
    if (r.frames.empty()) throw std::runtime_error("rawlog '" + name + "': contains no 3D-object observations");
    return r.frames;
}

}  // namespace simp::obs
