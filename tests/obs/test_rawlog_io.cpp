// Reading back a rawlog written by the project, through MRPT's own archive code.
#include <gtest/gtest.h>
#include <mrpt/io/CFileInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/ExampleRawlog.h>

#include <filesystem>

using simp::obs::CObservationObjects3D;

TEST(ExampleRawlog, ReadsBackEveryObservation) {
    std::filesystem::create_directories(SIMP_TEST_OUTPUT_DIR);
    const std::string path = std::string(SIMP_TEST_OUTPUT_DIR) + "/example_read.rawlog";
    simp::obs::ExampleRawlogParams p;
    p.frames = 5;
    p.cameras = 4;
    p.detections = 3;
    ASSERT_EQ(simp::obs::writeExampleRawlog(path, p), 20u);

    mrpt::io::CFileInputStream f(path);
    auto in = mrpt::serialization::archiveFrom(f);
    std::size_t frames = 0, observations = 0, detections = 0;
    for (;;) {
        mrpt::serialization::CSerializable::Ptr obj;
        try {
            obj = in.ReadObject();
        } catch (const mrpt::serialization::CExceptionEOF&) {
            break;
        }
        if (std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj)) continue;
        auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj);
        ASSERT_TRUE(sf) << "object " << frames << " is a " << obj->GetRuntimeClass()->className;
        ++frames;
        for (const auto& o : *sf) {
            auto det = std::dynamic_pointer_cast<CObservationObjects3D>(o);
            ASSERT_TRUE(det);
            ++observations;
            detections += det->size();
        }
    }
    EXPECT_EQ(frames, 5u);
    EXPECT_EQ(observations, 20u);
    EXPECT_EQ(detections, 60u);
}
