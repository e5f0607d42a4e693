#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/datetime.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/ExampleRawlog.h>
#include <simp/obs/InputLimits.h>
#include <simp/obs/ObjectClasses.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace simp::obs {

void validateExampleRawlogParams(const ExampleRawlogParams& p) {
    // A rawlog without frames is one the project's own reader rejects; the upper bounds keep
    // a typo from filling the disk (--frames -1 once wrapped to 2^64).
    const auto check = [](std::size_t v, std::size_t lo, std::size_t hi, const char* name) {
        if (v < lo || v > hi)
            throw std::invalid_argument(std::string("example rawlog: ") + name + " = " + std::to_string(v) +
                                        " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    };
    check(p.frames, 1, kMaxExampleFrames, "frames");
    check(p.cameras, 1, kMaxExampleCameras, "cameras");
    check(p.detections, 0, limits::kMaxDetectionsPerFrame, "detections");
    if (!(p.frame_period_s > 0 && p.frame_period_s <= 3600))
        throw std::invalid_argument("example rawlog: frame_period_s = " + std::to_string(p.frame_period_s) +
                                    " must be in (0, 3600] s");
}

std::size_t writeExampleRawlog(const std::string& path, const ExampleRawlogParams& params) {
    validateExampleRawlogParams(params);
    mrpt::io::CFileOutputStream file;
    if (!file.open(path)) throw std::runtime_error("rawlog '" + path + "': cannot open for writing");
    auto archive = mrpt::serialization::archiveFrom(file);
    std::mt19937_64 rng(params.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> cls(0, static_cast<int>(defaultClassNames().size()) - 1);
    // A fixed epoch keeps files byte-identical for the same seed.
    const auto t0 = mrpt::Clock::fromDouble(1.6e9);
    mrpt::img::TCamera K;
    K.ncols = 640;
    K.nrows = 480;
    K.setIntrinsicParamsFromValues(380.07, 379.66, 324.47, 237.79);
    std::size_t written = 0;
    for (std::size_t f = 0; f < params.frames; ++f) {
        mrpt::obs::CSensoryFrame sf;
        for (std::size_t c = 0; c < params.cameras; ++c) {
            auto obs = CObservationObjects3D::Create();
            obs->sensorLabel = "CAMERA_" + std::to_string(c);
            obs->timestamp = mrpt::Clock::fromDouble(mrpt::Clock::toDouble(t0) + f * params.frame_period_s);
            obs->setCameraPose(cameraPoseOnRobot(0.1, 0.0, 0.63, c * 2.0 * M_PI / params.cameras));
            obs->setIntrinsics(K);
            obs->setImageSize(640, 480);
            for (std::size_t d = 0; d < params.detections; ++d) {
                Detection3D det;
                det.class_id = static_cast<std::uint16_t>(cls(rng));
                det.confidence = static_cast<float>(0.5 + 0.5 * unit(rng));
                det.box_in_camera.center = {-1.0 + 2.0 * unit(rng), 0.2 * unit(rng), 1.5 + 3.0 * unit(rng)};
                det.box_in_camera.size = {0.4 + unit(rng), 0.5 + unit(rng), 0.4 + unit(rng)};
                det.box_in_camera.R =
                    Eigen::AngleAxisd(2.0 * M_PI * unit(rng), Eigen::Vector3d::UnitY()).toRotationMatrix();
                det.box_2d = ImageBox2D{100.0f, 120.0f, 220.0f, 300.0f};
                det.detector_id = static_cast<std::int64_t>(f * 100 + d);
                obs->addDetection(det);
            }
            sf.insert(obs);
            ++written;
        }
        // Rawlogs in MRPT's "actions + sensory frames" format alternate an action collection
        // (here: a small forward motion) with the frame; MRPT's tools expect the pair.
        mrpt::obs::CActionCollection acts;
        mrpt::obs::CActionRobotMovement2D move;
        move.timestamp = mrpt::Clock::fromDouble(mrpt::Clock::toDouble(t0) + f * params.frame_period_s);
        mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motion;
        move.computeFromOdometry(mrpt::poses::CPose2D(0.05, 0.0, 0.01), motion);
        acts.insert(move);
        archive << acts << sf;
    }
    return written;
}

}  // namespace simp::obs
