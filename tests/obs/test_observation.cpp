// CObservationObjects3D: frames, serialization (current and older versions), text, bad input.
#include <gtest/gtest.h>
#include <gmock/gmock.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CText.h>
#include <mrpt/serialization/CArchive.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/obs/ObjectClasses.h>

#include <cmath>
#include <limits>

using simp::obs::CObservationObjects3D;
using simp::obs::Detection3D;
using ::testing::HasSubstr;

namespace {

Detection3D makeDetection(std::uint16_t cls, double x, double y, double z) {
    Detection3D d;
    d.class_id = cls;
    d.confidence = 0.8f;
    d.box_in_camera.center = {x, y, z};
    d.box_in_camera.size = {0.6, 0.9, 1.2};
    d.box_in_camera.R = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
    return d;
}

CObservationObjects3D::Ptr makeObservation() {
    auto o = CObservationObjects3D::Create();
    o->sensorLabel = "CAMERA_1";
    o->timestamp = mrpt::Clock::fromDouble(1234.5);
    o->setCameraPose(simp::obs::cameraPoseOnRobot(0.1, 0.0, 0.63, M_PI / 2));
    mrpt::img::TCamera K;
    K.setIntrinsicParamsFromValues(380.07, 379.66, 324.47, 237.79);
    o->setIntrinsics(K);
    o->setImageSize(640, 480);
    auto d0 = makeDetection(4, 0.5, 0.2, 3.0);
    d0.box_2d = simp::obs::ImageBox2D{10, 20, 110, 220};
    d0.detector_id = 42;
    o->addDetection(d0);
    o->addDetection(makeDetection(9, -1.0, 0.1, 2.0));
    return o;
}

CObservationObjects3D::Ptr roundTrip(const CObservationObjects3D& o) {
    mrpt::io::CMemoryStream buf;
    auto arch = mrpt::serialization::archiveFrom(buf);
    arch << o;
    buf.Seek(0);
    auto obj = arch.ReadObject();
    auto back = std::dynamic_pointer_cast<CObservationObjects3D>(obj);
    if (!back) throw std::runtime_error("not a CObservationObjects3D");
    return back;
}

}  // namespace

TEST(CObservationObjects3D, CameraOpticalFrameConvention) {
    // A forward camera (yaw 0) sees a point 2 m along its optical axis (camera z) 2 m ahead of
    // the robot (robot x); camera x (right) is robot -y; camera y (down) is robot -z.
    const auto T = simp::obs::cameraPoseOnRobot(0.0, 0.0, 0.5, 0.0);
    mrpt::math::TPoint3D p;
    T.composePoint(0, 0, 2, p.x, p.y, p.z);
    EXPECT_NEAR(p.x, 2.0, 1e-12);
    EXPECT_NEAR(p.y, 0.0, 1e-12);
    EXPECT_NEAR(p.z, 0.5, 1e-12);
    T.composePoint(1, 0, 0, p.x, p.y, p.z);
    EXPECT_NEAR(p.y, -1.0, 1e-12);
    T.composePoint(0, 1, 0, p.x, p.y, p.z);
    EXPECT_NEAR(p.z, 0.5 - 1.0, 1e-12);
    // Left camera (yaw +90 deg): optical axis along robot +y.
    const auto L = simp::obs::cameraPoseOnRobot(0.0, 0.0, 0.0, M_PI / 2);
    L.composePoint(0, 0, 3, p.x, p.y, p.z);
    EXPECT_NEAR(p.x, 0.0, 1e-12);
    EXPECT_NEAR(p.y, 3.0, 1e-12);
}

TEST(CObservationObjects3D, CornersAndFootprintInEveryFrame) {
    auto o = CObservationObjects3D::Create();
    o->setCameraPose(simp::obs::cameraPoseOnRobot(0.0, 0.0, 0.5, 0.0));
    Detection3D d;
    d.class_id = 4;
    d.box_in_camera.center = {0.0, 0.0, 3.0};  // 3 m ahead, at camera height
    d.box_in_camera.size = {1.0, 0.8, 2.0};    // W across, H vertical, L along the view
    o->addDetection(d);
    const auto robot = o->cornersInRobot(0);
    const auto cam = o->cornersInCamera(0);
    // Corner 0 = (-W/2, -H/2, -L/2) in camera = 2 m ahead, 0.5 m left (camera -x), 0.4 m up (camera -y).
    EXPECT_NEAR(cam[0].z(), 2.0, 1e-12);
    EXPECT_NEAR(robot[0].x(), 2.0, 1e-12);
    EXPECT_NEAR(robot[0].y(), 0.5, 1e-12);
    EXPECT_NEAR(robot[0].z(), 0.9, 1e-12);
    // Robot at (10, 5) facing +y: the box centre is 3 m along world +y.
    const mrpt::poses::CPose3D world_T_robot(10, 5, 0, M_PI / 2, 0, 0);
    const auto box_w = o->boxInWorld(0, world_T_robot);
    EXPECT_NEAR(box_w.center.x(), 10.0, 1e-12);
    EXPECT_NEAR(box_w.center.y(), 8.0, 1e-12);
    const auto fp = o->footprintInWorld(0, world_T_robot);
    ASSERT_EQ(fp.n, 4u);
    EXPECT_NEAR(fp.area(), 1.0 * 2.0, 1e-9);  // W x L on the ground
    EXPECT_NEAR(fp.centroid().x(), 10.0, 1e-9);
    EXPECT_NEAR(fp.centroid().y(), 8.0, 1e-9);
    EXPECT_NEAR(o->footprintInRobot(0).area(), 2.0, 1e-9);
    const auto w = o->cornersInWorld(0, world_T_robot);
    EXPECT_NEAR(w[0].x(), 10.0 - 0.5, 1e-12);  // robot +y (left) is world -x when facing +y
    EXPECT_NEAR(w[0].y(), 5.0 + 2.0, 1e-12);
}

TEST(CObservationObjects3D, SerializationRoundTripCurrentVersion) {
    const auto o = makeObservation();
    const auto b = roundTrip(*o);
    EXPECT_EQ(b->sensorLabel, "CAMERA_1");
    EXPECT_EQ(b->timestamp, o->timestamp);
    EXPECT_TRUE(b->cameraPose().asTPose() == o->cameraPose().asTPose());
    ASSERT_TRUE(b->intrinsics().has_value());
    EXPECT_DOUBLE_EQ(b->intrinsics()->fx(), 380.07);
    EXPECT_EQ(b->imageWidth(), 640u);
    ASSERT_EQ(b->size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const auto& x = o->detections()[i];
        const auto& y = b->detections()[i];
        EXPECT_EQ(x.class_id, y.class_id);
        EXPECT_FLOAT_EQ(x.confidence, y.confidence);
        EXPECT_TRUE(x.box_in_camera.center.isApprox(y.box_in_camera.center, 1e-15));
        EXPECT_TRUE(x.box_in_camera.size.isApprox(y.box_in_camera.size, 1e-15));
        EXPECT_LT((x.box_in_camera.R - y.box_in_camera.R).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_EQ(x.detector_id, y.detector_id);
        EXPECT_EQ(x.box_2d.has_value(), y.box_2d.has_value());
    }
    EXPECT_EQ(b->detections()[0].box_2d->x_max, 110.0f);
    EXPECT_EQ(b->classNameOf(b->detections()[1]), "cabinet");
    // The robot-frame cache is rebuilt on load.
    EXPECT_NEAR(b->footprintInRobot(1).area(), o->footprintInRobot(1).area(), 1e-12);
}

TEST(CObservationObjects3D, SerializationReadsVersion0) {
    const auto o = makeObservation();
    CObservationObjects3D::setWriteVersion(0);
    CObservationObjects3D::Ptr b;
    try {
        b = roundTrip(*o);
    } catch (...) {
        CObservationObjects3D::setWriteVersion(CObservationObjects3D::currentVersion());
        throw;
    }
    CObservationObjects3D::setWriteVersion(CObservationObjects3D::currentVersion());
    ASSERT_EQ(b->size(), 2u);
    // Version 0 has no intrinsics, image size, 2D boxes or detector ids: defaults come back.
    EXPECT_FALSE(b->intrinsics().has_value());
    EXPECT_EQ(b->imageWidth(), 640u);
    EXPECT_FALSE(b->detections()[0].box_2d.has_value());
    EXPECT_FALSE(b->detections()[0].detector_id.has_value());
    EXPECT_TRUE(b->detections()[0].box_in_camera.center.isApprox(o->detections()[0].box_in_camera.center));
    EXPECT_EQ(b->sensorLabel, "CAMERA_1");
}

TEST(CObservationObjects3D, UnknownVersionThrows) {
    EXPECT_THROW(CObservationObjects3D::setWriteVersion(CObservationObjects3D::currentVersion() + 1),
                 std::invalid_argument);
    // A stream that claims a future version must be refused by the reader.
    const auto o = makeObservation();
    mrpt::io::CMemoryStream buf;
    auto arch = mrpt::serialization::archiveFrom(buf);
    arch << *o;
    // Layout: class-name header, then the version byte; patch it to 99.
    auto* bytes = static_cast<uint8_t*>(const_cast<void*>(buf.getRawBufferData()));
    const std::string name = "simp::obs::CObservationObjects3D";
    const std::string raw(reinterpret_cast<char*>(bytes), buf.getTotalBytesCount());
    const auto pos = raw.find(name);
    ASSERT_NE(pos, std::string::npos);
    bytes[pos + name.size()] = 99;
    buf.Seek(0);
    EXPECT_ANY_THROW(arch.ReadObject());
}

/// Whitespace-separated tokens of a line.
std::vector<std::string> tokens(const std::string& line) {
    std::istringstream s(line);
    std::vector<std::string> t;
    for (std::string x; s >> x;) t.push_back(x);
    return t;
}

TEST(CObservationObjects3D, DescriptionTextIsATableWithClassNamesAndUnits) {
    const auto o = makeObservation();
    std::ostringstream s;
    o->getDescriptionAsText(s);
    const auto text = s.str();
    EXPECT_THAT(text, HasSubstr("Detections: 2"));
    EXPECT_THAT(text, HasSubstr("fx=380.07"));
    EXPECT_THAT(text, HasSubstr("CAMERA_1"));  // base class part
    // The table: a header line with the column names, then one line per detection, each with
    // exactly the header's number of columns.
    std::istringstream lines(text);
    std::vector<std::vector<std::string>> table;
    for (std::string line; std::getline(lines, line);) {
        const auto t = tokens(line);
        if (!table.empty() || (!t.empty() && t[0] == "detection")) table.push_back(t);
    }
    const auto& names = CObservationObjects3D::detectionColumnNames();
    ASSERT_EQ(table.size(), 3u) << text;
    EXPECT_EQ(table[0], names);
    for (const auto& row : table) ASSERT_EQ(row.size(), names.size()) << text;
    EXPECT_EQ(table[1][1], "4");
    EXPECT_EQ(table[1][2], "table");
    EXPECT_EQ(table[1][3], "0.8");
    EXPECT_EQ(table[1][4], "0.5");    // cx (m)
    EXPECT_EQ(table[1][8], "0.9");    // H (m)
    EXPECT_EQ(table[1][14], "10");    // x_min (px)
    EXPECT_EQ(table[1][18], "42");    // detector_id
    EXPECT_EQ(table[2][2], "cabinet");
    EXPECT_EQ(table[2][14], "nan");   // no 2D box
    EXPECT_EQ(table[2][18], "-1");    // no detector id
}

TEST(CObservationObjects3D, ExportTxtWritesOneRowPerDetectionWithFixedColumns) {
    auto o = makeObservation();
    ASSERT_TRUE(o->exportTxtSupported());
    const std::size_t columns = 7 + CObservationObjects3D::detectionColumnNames().size();  // without rawlog-edit's time
    EXPECT_EQ(tokens(o->exportTxtHeader()).size(), columns);
    // rawlog-edit writes "%16.6f " before the row: the rows after the first carry that time themselves.
    std::istringstream rows(o->exportTxtDataRow());
    std::vector<std::vector<std::string>> table;
    for (std::string line; std::getline(rows, line);) table.push_back(tokens(line));
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[0].size(), columns);
    ASSERT_EQ(table[1].size(), columns + 1);
    EXPECT_NEAR(std::stod(table[1][0]), mrpt::Clock::toDouble(o->timestamp), 1e-6);
    EXPECT_EQ(table[0][6], "2");  // num_detections
    EXPECT_EQ(table[0][9], "table");
    EXPECT_EQ(table[1][1 + 9], "cabinet");
    EXPECT_NEAR(std::stod(table[0][11]), 0.5, 1e-9);  // cx of detection 0

    // A multi-word class name stays one column; no detections: one placeholder row.
    auto names = o->classNames();
    names[9] = "filing cabinet";
    o->setClassNames(names);
    EXPECT_THAT(o->exportTxtDataRow(), HasSubstr(" filing_cabinet "));
    o->setDetections({});
    const auto empty = tokens(o->exportTxtDataRow());
    ASSERT_EQ(empty.size(), columns);
    EXPECT_EQ(empty[6], "0");
    EXPECT_EQ(empty[7], "-1");
}

TEST(CObservationObjects3D, IsVisualizableForRawLogViewersThreeDView) {
    // RawLogViewer 2.5.8 draws any selected object that is an mrpt::opengl::Visualizable.
    const mrpt::serialization::CSerializable::Ptr obj = makeObservation();
    const auto viz = std::dynamic_pointer_cast<mrpt::opengl::Visualizable>(obj);
    ASSERT_TRUE(viz);
    const auto set = viz->getVisualization();
    std::size_t boxes = 0, texts = 0;
    for (const auto& child : *set) {
        boxes += std::dynamic_pointer_cast<mrpt::opengl::CBox>(child) != nullptr;
        if (const auto t = std::dynamic_pointer_cast<mrpt::opengl::CText>(child)) {
            ++texts;
            EXPECT_THAT(t->getString(), ::testing::AnyOf(HasSubstr("table 0.80"), HasSubstr("cabinet")));
        }
    }
    EXPECT_EQ(boxes, 2u);
    EXPECT_EQ(texts, 2u);
}

// ---------------------------------------------------------------- bad input
class BadDetection : public ::testing::Test {
   protected:
    CObservationObjects3D obs;
    Detection3D good = makeDetection(1, 0, 0, 2);
    void expectRejected(const Detection3D& d, const std::string& field) {
        try {
            obs.addDetection(d);
            FAIL() << "accepted a detection with bad " << field;
        } catch (const std::invalid_argument& e) {
            EXPECT_THAT(e.what(), HasSubstr("detection #0"));
            EXPECT_THAT(e.what(), HasSubstr("'" + field + "'"));
        }
        EXPECT_TRUE(obs.empty());
    }
};

TEST_F(BadDetection, NaNCentre) {
    auto d = good;
    d.box_in_camera.center.x() = std::numeric_limits<double>::quiet_NaN();
    expectRejected(d, "center");
}
TEST_F(BadDetection, InfiniteSize) {
    auto d = good;
    d.box_in_camera.size.z() = std::numeric_limits<double>::infinity();
    expectRejected(d, "size");
}
TEST_F(BadDetection, NegativeSize) {
    auto d = good;
    d.box_in_camera.size.y() = -0.2;
    expectRejected(d, "size");
}
TEST_F(BadDetection, ConfidenceAboveOne) {
    auto d = good;
    d.confidence = 1.5f;
    expectRejected(d, "confidence");
}
TEST_F(BadDetection, ConfidenceNaN) {
    auto d = good;
    d.confidence = std::numeric_limits<float>::quiet_NaN();
    expectRejected(d, "confidence");
}
TEST_F(BadDetection, ClassIdOutOfRange) {
    auto d = good;
    d.class_id = static_cast<std::uint16_t>(simp::obs::defaultClassNames().size());
    expectRejected(d, "class_id");
}
TEST_F(BadDetection, NotARotation) {
    auto d = good;
    d.box_in_camera.R(0, 0) = 2.0;
    expectRejected(d, "rotation");
}
TEST_F(BadDetection, InvertedImageBox) {
    auto d = good;
    d.box_2d = simp::obs::ImageBox2D{100, 10, 50, 20};
    expectRejected(d, "box_2d");
}
TEST_F(BadDetection, SetDetectionsIsAllOrNothing) {
    auto bad = good;
    bad.confidence = -0.1f;
    EXPECT_THROW(obs.setDetections({good, bad}), std::invalid_argument);
    EXPECT_TRUE(obs.empty());
    try {
        obs.setDetections({good, bad});
    } catch (const std::invalid_argument& e) {
        EXPECT_THAT(e.what(), HasSubstr("detection #1"));
    }
}
TEST_F(BadDetection, ShrinkingClassListBelowAUsedIdIsRejected) {
    obs.addDetection(makeDetection(9, 0, 0, 2));
    EXPECT_THROW(obs.setClassNames({"sink", "door"}), std::invalid_argument);
    EXPECT_EQ(obs.classNames().size(), 14u);
}

TEST(CObservationObjects3D, CorruptedNumberInArchiveIsRejectedOnLoad) {
    // Write a valid observation, then overwrite the confidence of detection 0 with 7.0f.
    auto o = CObservationObjects3D::Create();
    auto d = makeDetection(2, 0, 0, 2);
    d.confidence = 0.3125f;  // exact in binary: easy to find in the stream
    o->addDetection(d);
    mrpt::io::CMemoryStream buf;
    auto arch = mrpt::serialization::archiveFrom(buf);
    arch << *o;
    auto* bytes = static_cast<uint8_t*>(const_cast<void*>(buf.getRawBufferData()));
    const float needle = 0.3125f, patched = 7.0f;
    bool found = false;
    for (std::size_t i = 0; i + 4 <= buf.getTotalBytesCount(); ++i)
        if (std::memcmp(bytes + i, &needle, 4) == 0) {
            std::memcpy(bytes + i, &patched, 4);
            found = true;
            break;
        }
    ASSERT_TRUE(found);
    buf.Seek(0);
    try {
        arch.ReadObject();
        FAIL() << "corrupted confidence accepted";
    } catch (const std::exception& e) {
        EXPECT_THAT(e.what(), HasSubstr("detection #0"));
        EXPECT_THAT(e.what(), HasSubstr("confidence"));
    }
}
