// The authors' map format: pixel convention, rectangle fit, import of the hand-made example
// (every machine) and of the real simp-office map (when present), export, round trips, errors.
#include "TestUtil.h"

#include <gmock/gmock.h>
#include <opencv2/imgcodecs.hpp>
#include <nlohmann/json.hpp>
#include <simp/geometry/Footprint.h>
#include <simp/world/MapConvertApps.h>
#include <simp/world/SimpFormat.h>
#include <simp/world/SimpPixels.h>

#include <cmath>
#include <fstream>
#include <map>

using namespace simp::world;
using simp_test::freshDir;
using simp_test::errorOf;
using simp_test::writeFile;
using ::testing::HasSubstr;

namespace {

const std::string kExample = std::string(SIMP_SOURCE_DIR) + "/tests/data/simp_format_example";
const std::string kOffice = std::string(SIMP_SHARED_DATA_DIR) + "/simp-office";

nlohmann::json readJson(const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

/// Copies the example into a fresh folder so that a test can break one file.
std::string exampleCopy() {
    const std::string dir = freshDir() + "/simp";
    std::filesystem::create_directories(dir);
    for (const auto& e : std::filesystem::directory_iterator(kExample))
        std::filesystem::copy_file(e.path(), dir + "/" + e.path().filename().string());
    return dir;
}

SimpPixelFrame frameOf(const World& w) {
    return SimpPixelFrame{w.floorplan.getResolution(), w.floorplan.getXMin(), w.floorplan.getYMin(),
                          static_cast<int>(w.floorplan.getSizeY())};
}

/// Footprint corners of an upright box, in the authors' continuous pixel coordinates.
std::vector<Eigen::Vector2d> footprintPx(const MapObject& o, const SimpPixelFrame& px) {
    std::vector<Eigen::Vector2d> out;
    const auto corners = o.box.corners();
    for (int i = 0; i < 4; ++i) out.push_back(px.toPixel(corners[static_cast<std::size_t>(i)].head<2>()));
    return out;
}

/// Largest over published corners of the distance (max norm, px) to the nearest fitted corner.
double cornerDeviationPx(const std::vector<Eigen::Vector2d>& fitted, const std::vector<int>& published) {
    double worst = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        const Eigen::Vector2d p(published[2 * k], published[2 * k + 1]);
        double best = 1e9;
        for (const auto& f : fitted) best = std::min(best, (f - p).cwiseAbs().maxCoeff());
        worst = std::max(worst, best);
    }
    return worst;
}

void expectSameWorld(const World& a, const World& b, double corner_tol_m) {
    ASSERT_EQ(a.objects.objects.size(), b.objects.objects.size());
    EXPECT_EQ(a.objects.class_names, b.objects.class_names);
    for (std::size_t i = 0; i < a.objects.objects.size(); ++i) {
        const MapObject &x = a.objects.objects[i], &y = b.objects.objects[i];
        EXPECT_EQ(x.id, y.id);
        EXPECT_EQ(x.class_id, y.class_id);
        EXPECT_EQ(x.room_id, y.room_id) << "object " << x.id;
        const auto cx = x.box.corners(), cy = y.box.corners();
        for (std::size_t k = 0; k < 8; ++k) EXPECT_LT((cx[k] - cy[k]).norm(), corner_tol_m) << "object " << x.id;
        ASSERT_TRUE(x.noise && y.noise);
        // The noise is carried exactly (continuous numbers, no pixel rounding).
        EXPECT_LT((x.box.R.topLeftCorner<2, 2>() * x.noise->mean_m + x.box.center.head<2>() -
                   y.box.R.topLeftCorner<2, 2>() * y.noise->mean_m - y.box.center.head<2>())
                      .norm(),
                  1e-9);
        const Eigen::Matrix2d Sx = x.box.R.topLeftCorner<2, 2>() * x.noise->cov_m2 * x.box.R.topLeftCorner<2, 2>().transpose();
        const Eigen::Matrix2d Sy = y.box.R.topLeftCorner<2, 2>() * y.noise->cov_m2 * y.box.R.topLeftCorner<2, 2>().transpose();
        EXPECT_NEAR(Sx(0, 0), Sy(0, 0), 1e-12);
        EXPECT_NEAR(Sx(1, 1), Sy(1, 1), 1e-12);
    }
    ASSERT_EQ(a.floorplan.getSizeX(), b.floorplan.getSizeX());
    ASSERT_EQ(a.floorplan.getSizeY(), b.floorplan.getSizeY());
    EXPECT_EQ(a.floorplan.getXMin(), b.floorplan.getXMin());
    EXPECT_EQ(a.floorplan.getYMin(), b.floorplan.getYMin());
    int differing = 0;
    for (unsigned y = 0; y < a.floorplan.getSizeY(); ++y)
        for (unsigned x = 0; x < a.floorplan.getSizeX(); ++x)
            differing += std::abs(a.floorplan.getCell(x, y) - b.floorplan.getCell(x, y)) > 0.01f;
    EXPECT_EQ(differing, 0);
    EXPECT_EQ(cv::countNonZero(a.rooms.ids != b.rooms.ids), 0);
}

}  // namespace

TEST(SimpPixels, AuthorsConventionAndInverse) {
    const SimpPixelFrame px{0.05, -13.9155, -11.04537, 280};
    // u = round((x - ox) / res), v = rows - round((y - oy) / res): rows, not rows - 1.
    EXPECT_EQ(px.toPixelRounded({-13.9155, -11.04537}), Eigen::Vector2i(0, 280));
    EXPECT_EQ(px.toPixelRounded({-13.9155 + 0.05 * 10.4, -11.04537 + 0.05 * 3.6}), Eigen::Vector2i(10, 276));
    // Half-way values round to even, as numpy.round.
    EXPECT_EQ(px.toPixelRounded({-13.9155 + 0.05 * 2.5, -11.04537}).x(), 2);
    const Eigen::Vector2d uv(123.25, 45.75);
    EXPECT_LT((px.toPixel(px.toWorld(uv)) - uv).norm(), 1e-10);
}

TEST(FitRectangle, ExactRectangleAndRoundedCorners) {
    // A 2 x 1 rectangle rotated by 0.3 rad, corners given clockwise.
    const double yaw = 0.3;
    const Eigen::Vector2d c(1, 2), ax(std::cos(yaw), std::sin(yaw)), ay(-std::sin(yaw), std::cos(yaw));
    const std::array<Eigen::Vector2d, 4> pts = {c - ax - 0.5 * ay, c - ax + 0.5 * ay, c + ax + 0.5 * ay, c + ax - 0.5 * ay};
    const RectangleFit f = fitRectangle(pts);
    EXPECT_NEAR(f.center_m.x(), 1, 1e-12);
    EXPECT_NEAR(f.center_m.y(), 2, 1e-12);
    EXPECT_NEAR(f.yaw_rad, 0.3, 1e-12);
    EXPECT_NEAR(f.length_x_m, 2, 1e-12);
    EXPECT_NEAR(f.length_y_m, 1, 1e-12);
    // Degenerate: all corners on a line.
    EXPECT_THAT(errorOf([] {
                    fitRectangle({Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(2, 0), Eigen::Vector2d(3, 0)});
                }),
                HasSubstr("degenerate"));
}

TEST(SimpImport, HandMadeExample) {
    const World w = importSimpMap(kExample);
    // Floor plan: 30 x 20 px at 0.1 m, origin not a multiple of the resolution, honoured.
    ASSERT_EQ(w.floorplan.getSizeX(), 30u);
    ASSERT_EQ(w.floorplan.getSizeY(), 20u);
    EXPECT_FLOAT_EQ(w.floorplan.getXMin(), -1.23f);
    EXPECT_FLOAT_EQ(w.floorplan.getYMin(), -0.77f);
    EXPECT_LT(w.floorplan.getCell(0, 0), 0.01f);     // wall corner
    EXPECT_GT(w.floorplan.getCell(5, 5), 0.99f);     // free inside
    EXPECT_FLOAT_EQ(w.floorplan.getCell(27, 18), 0.5f);  // unknown block (image rows 1-2, cols 26-28)
    ASSERT_EQ(w.objects.class_names.size(), 14u);
    EXPECT_TRUE(w.objects.class_noise[4].has_value());
    EXPECT_TRUE(w.objects.class_noise[9].has_value());
    EXPECT_FALSE(w.objects.class_noise[10].has_value());
    // class_noise.csv row 9: (0, 0, 1, 3) px -> cov diag(0.1^2, 0.3^2) m^2.
    EXPECT_NEAR(w.objects.class_noise[9]->cov_m2(1, 1), 0.09, 1e-12);
    ASSERT_EQ(w.objects.rooms.size(), 2u);
    EXPECT_EQ(w.objects.rooms[1].id, 2);
    EXPECT_EQ(w.objects.rooms[1].category, "kitchen");

    ASSERT_EQ(w.objects.objects.size(), 3u);
    const MapObject& table = w.objects.objects[0];
    EXPECT_EQ(table.id, 10);
    EXPECT_EQ(table.class_id, 4);
    EXPECT_NEAR(table.box.center.x(), -0.53, 1e-12);
    EXPECT_NEAR(table.box.center.y(), 0.53, 1e-12);
    EXPECT_NEAR(table.box.center.z(), 0.375, 1e-12);  // default table height 0.75 / 2
    EXPECT_NEAR(table.box.size.x(), 0.8, 1e-12);
    EXPECT_NEAR(table.box.size.y(), 0.6, 1e-12);
    EXPECT_NEAR(simp::geometry::yawOf(table.box), 0.0, 1e-12);
    EXPECT_EQ(table.room_id, 1);
    // mean pixel (7.5, 6.5) = centre + (0.5, -0.5) px -> (+0.05, +0.05) m; scales (2, 4) px.
    EXPECT_NEAR(table.noise->mean_m.x(), 0.05, 1e-12);
    EXPECT_NEAR(table.noise->mean_m.y(), 0.05, 1e-12);
    EXPECT_NEAR(table.noise->cov_m2(0, 0), 0.04, 1e-12);
    EXPECT_NEAR(table.noise->cov_m2(1, 1), 0.16, 1e-12);

    // The cabinet's (sx, sy) are its class's swapped: its x axis is the image's v axis.
    const MapObject& cabinet = w.objects.objects[1];
    EXPECT_NEAR(cabinet.box.center.x(), 0.97, 1e-12);
    EXPECT_NEAR(cabinet.box.center.y(), 0.43, 1e-12);
    EXPECT_NEAR(std::abs(simp::geometry::yawOf(cabinet.box)), M_PI / 2, 1e-12);
    EXPECT_NEAR(cabinet.box.size.x(), 1.0, 1e-12);
    EXPECT_NEAR(cabinet.box.size.y(), 0.4, 1e-12);
    EXPECT_NEAR(cabinet.box.size.z(), 1.8, 1e-12);
    EXPECT_EQ(cabinet.room_id, 2);
    // In its own frame the noise equals the class model: diag(0.1^2, 0.3^2).
    EXPECT_NEAR(cabinet.noise->cov_m2(0, 0), 0.01, 1e-12);
    EXPECT_NEAR(cabinet.noise->cov_m2(1, 1), 0.09, 1e-12);
    EXPECT_NEAR(cabinet.noise->cov_m2(0, 1), 0.0, 1e-12);

    // The chair's class is not modelled: its x axis is the longer side.
    const MapObject& chair = w.objects.objects[2];
    EXPECT_NEAR(chair.box.center.x(), -0.68, 1e-12);
    EXPECT_NEAR(chair.box.center.y(), -0.27, 1e-12);
    EXPECT_NEAR(simp::geometry::yawOf(chair.box), std::atan2(-2.0, 4.0), 1e-12);
    EXPECT_NEAR(chair.box.size.x(), std::sqrt(0.2), 1e-12);
    EXPECT_NEAR(chair.box.size.y(), std::sqrt(0.05), 1e-12);
    EXPECT_EQ(chair.room_id, 1);
}

TEST(SimpImport, ExampleExportImportRoundTrip) {
    const std::string dir = freshDir();
    const World a = importSimpMap(kExample);
    exportSimpMap(a, dir + "/exported");
    // The exported corners are the published ones (every fitted corner is within 0.5 px).
    const auto src = readJson(kExample + "/global_variance.json");
    const auto out = readJson(dir + "/exported/global_variance.json");
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_LT(cornerDeviationPx(footprintPx(a.objects.objects[i], frameOf(a)), src["corners"][i].get<std::vector<int>>()),
                  0.5);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(out["mx"][i].get<double>(), src["mx"][i].get<double>(), 1e-9);
        EXPECT_NEAR(out["my"][i].get<double>(), src["my"][i].get<double>(), 1e-9);
        EXPECT_NEAR(out["sx"][i].get<double>(), src["sx"][i].get<double>(), 1e-9);
        EXPECT_NEAR(out["sy"][i].get<double>(), src["sy"][i].get<double>(), 1e-9);
    }
    const World b = importSimpMap(dir + "/exported");
    expectSameWorld(a, b, 1e-9);
    // The exported floor.config lists the table and the chair in room "0", as the source.
    const auto fc = readJson(dir + "/exported/floor.config");
    ASSERT_EQ(fc["rooms"].size(), 2u);
    EXPECT_EQ(fc["rooms"][0]["objects"].size(), 2u);
    EXPECT_EQ(fc["rooms"][0]["objects"][0]["position"], nlohmann::json({3, 4, 12, 11}));
    EXPECT_EQ(fc["semantic"]["categories"], nlohmann::json({"office", "kitchen"}));
}

TEST(SimpImport, WorldDirectoryRoundTrip) {
    const std::string dir = freshDir();
    const World a = importSimpMap(kExample);
    saveWorld(a, dir + "/w");
    const World b = loadWorld(dir + "/w");
    expectSameWorld(a, b, 1e-12);
}

TEST(SimpImport, HeightsFromIni) {
    const std::string dir = freshDir();
    writeFile(dir + "/h.ini", "[class_heights]\ntable = 0.72\nfire_extinguisher = 0.5\n");
    const SimpImportOptions opt = loadSimpImportOptions(dir + "/h.ini");
    const World w = importSimpMap(kExample, opt);
    EXPECT_NEAR(w.objects.objects[0].box.size.z(), 0.72, 1e-12);
    EXPECT_NEAR(w.objects.objects[0].box.center.z(), 0.36, 1e-12);
    writeFile(dir + "/bad.ini", "[class_heights]\ntable = -1\n");
    EXPECT_THAT(errorOf([&] { loadSimpImportOptions(dir + "/bad.ini"); }),
                HasSubstr("bad.ini: [class_heights] table"));
}

TEST(SimpImport, MissingDirectory) {
    EXPECT_THAT(errorOf([] { importSimpMap("/nonexistent/simp"); }), HasSubstr("'/nonexistent/simp' does not exist"));
}

TEST(SimpImport, MissingGlobalVariance) {
    const std::string dir = exampleCopy();
    std::filesystem::remove(dir + "/global_variance.json");
    EXPECT_THAT(errorOf([&] { importSimpMap(dir); }), HasSubstr("global_variance.json: file not found"));
}

TEST(SimpImport, MissingMapYaml) {
    const std::string dir = exampleCopy();
    std::filesystem::remove(dir + "/Map.yaml");
    EXPECT_THAT(errorOf([&] { importSimpMap(dir); }), HasSubstr("Map.yaml: missing"));
}

TEST(SimpImport, MissingClassesKey) {
    const std::string dir = exampleCopy();
    writeFile(dir + "/floor.config", R"({"semantic": {"categories": ["office"]}})");
    EXPECT_THAT(errorOf([&] { importSimpMap(dir); }), HasSubstr("floor.config: semantic.classes: missing"));
}

TEST(SimpImport, ArraysOfDifferentLength) {
    const std::string dir = exampleCopy();
    auto gv = readJson(dir + "/global_variance.json");
    gv["sx"].erase(gv["sx"].begin());
    writeFile(dir + "/global_variance.json", gv.dump());
    EXPECT_THAT(errorOf([&] { importSimpMap(dir); }), HasSubstr("global_variance.json: sx: expected 3 numbers"));
}

TEST(SimpImport, BadCorners) {
    const std::string dir = exampleCopy();
    auto gv = readJson(dir + "/global_variance.json");
    gv["corners"][1] = {1, 2, 3};
    writeFile(dir + "/global_variance.json", gv.dump());
    EXPECT_THAT(errorOf([&] { importSimpMap(dir); }),
                HasSubstr("global_variance.json: corners[1]: expected 8 numbers"));
}

TEST(SimpImport, CategoryOutOfRange) {
    const std::string dir = exampleCopy();
    auto gv = readJson(dir + "/global_variance.json");
    gv["category"][2] = 14;
    writeFile(dir + "/global_variance.json", gv.dump());
    EXPECT_THAT(errorOf([&] { importSimpMap(dir); }),
                HasSubstr("global_variance.json: category[2]: expected a class index in [0, 14)"));
}

TEST(SimpImport, ClassMeanIsTheMeanOfItsObjectsOffsetsInTheClassFrame) {
    // The table's mean pixel moves from (7.5, 6.5) to (8.5, 6.5): centre (7, 7) + (1.5, -0.5) px
    // -> world offset (0.15, 0.05) m = its box frame (yaw 0). Its box is 0.8 x 0.6 m, so the class
    // noise frame (y along the longer side) is turned by +90 deg: (0.05, -0.15) m. class_noise.csv
    // says (0.5, -0.5) px = (0.05, -0.05) m; the objects' models are what detections follow.
    const std::string dir = exampleCopy();
    auto gv = readJson(dir + "/global_variance.json");
    gv["mx"][0] = 8.5;
    writeFile(dir + "/global_variance.json", gv.dump());
    const World w = importSimpMap(dir);
    ASSERT_TRUE(w.objects.class_noise[4].has_value());
    EXPECT_NEAR(w.objects.class_noise[4]->mean_m.x(), 0.05, 1e-12);
    EXPECT_NEAR(w.objects.class_noise[4]->mean_m.y(), -0.15, 1e-12);
    // Its spread stays the file's: (2, 4) px at 0.1 m/px.
    EXPECT_NEAR(w.objects.class_noise[4]->cov_m2(0, 0), 0.04, 1e-12);
    EXPECT_NEAR(w.objects.class_noise[4]->cov_m2(1, 1), 0.16, 1e-12);
    // The cabinet's mean pixel is its centre: its class mean is zero.
    EXPECT_NEAR(w.objects.class_noise[9]->mean_m.norm(), 0.0, 1e-12);
}

TEST(SimpImport, ClassNoiseRowHalfFilled) {
    const std::string dir = exampleCopy();
    writeFile(dir + "/class_noise.csv", "category,mx,my,sx,sy,b\n0,1,2,,,\n");
    EXPECT_THAT(errorOf([&] { importSimpMap(dir); }), HasSubstr("class_noise.csv: line 2: either all of"));
}

TEST(SimpImport, UnknownClassWithoutHeight) {
    const std::string dir = exampleCopy();
    auto fc = readJson(dir + "/floor.config");
    fc["semantic"]["classes"][4] = "piano";
    writeFile(dir + "/floor.config", fc.dump());
    EXPECT_THAT(errorOf([&] { importSimpMap(dir); }),
                HasSubstr("floor.config: semantic.classes[4]: no height for class 'piano'"));
}

TEST(SimpImport, MissingNamedRoomRaster) {
    const std::string dir = exampleCopy();
    std::filesystem::remove(dir + "/roomseg.pgm");
    EXPECT_THAT(errorOf([&] { importSimpMap(dir); }), HasSubstr("floor.config: roomSeg: file"));
}

TEST(SimpExport, WithoutRoomsOrNoiseModels) {
    const std::string dir = freshDir();
    World w = importSimpMap(kExample);
    w.rooms = RoomMap{};
    w.objects.rooms.clear();
    for (auto& o : w.objects.objects) {
        o.noise.reset();
        o.room_id = 0;
    }
    exportSimpMap(w, dir + "/d");
    const cv::Mat roomseg = cv::imread(dir + "/d/roomseg.png", cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(roomseg.empty());
    EXPECT_EQ(roomseg.type(), CV_8UC1);
    EXPECT_EQ(cv::countNonZero(roomseg), 0);
    const auto gv = readJson(dir + "/d/global_variance.json");
    // Table: class model (0.5, -0.5, 2, 4) px at yaw 0 -> mean at centre (7, 7) + (0.5, +0.5) px
    // (class y = world y = -v), scales (2, 4).
    EXPECT_NEAR(gv["mx"][0].get<double>(), 7.5, 1e-9);
    EXPECT_NEAR(gv["my"][0].get<double>(), 7.5, 1e-9);
    EXPECT_NEAR(gv["sx"][0].get<double>(), 2.0, 1e-9);
    EXPECT_NEAR(gv["sy"][0].get<double>(), 4.0, 1e-9);
    // Chair: no model at all -> the default NoiseModel (sigma 0.2 m = 2 px at 0.1 m/px).
    EXPECT_NEAR(gv["sx"][2].get<double>(), 2.0, 1e-9);
    EXPECT_NEAR(gv["sy"][2].get<double>(), 2.0, 1e-9);
    std::ifstream csv(dir + "/d/class_noise.csv");
    std::string header, row0;
    std::getline(csv, header);
    std::getline(csv, row0);
    EXPECT_EQ(header, "category,mx,my,sx,sy,b");
    EXPECT_EQ(row0, "0,,,,,");
}

TEST(SimpExport, RoomIdsAbove255AreRejected) {
    const std::string dir = freshDir();
    World w = importSimpMap(kExample);
    w.rooms.ids(5, 5) = 300;
    EXPECT_THAT(errorOf([&] { exportSimpMap(w, dir + "/d"); }), HasSubstr("roomseg.png: room id 300 does not fit 8 bits"));
}

TEST(MapConvertApps, ImportThenExportInProcess) {
    const std::string dir = freshDir();
    const std::string w = dir + "/w", d = dir + "/d";
    const char* imp[] = {"simp-import-map", "--simp-dir", kExample.c_str(), "--out", w.c_str()};
    ImportMapApp app;
    app.initialize(5, imp);
    std::ostringstream out;
    EXPECT_EQ(app.run(out), 0);
    EXPECT_THAT(out.str(), HasSubstr("Objects: 3 in 14 classes"));
    EXPECT_THAT(out.str(), HasSubstr("  cabinet: 1\n"));
    EXPECT_TRUE(std::filesystem::exists(w + "/objects.json"));
    const char* exp[] = {"simp-export-map", "--world", w.c_str(), "--out", d.c_str()};
    ExportMapApp ex;
    ex.initialize(5, exp);
    EXPECT_EQ(ex.run(out), 0);
    for (const char* f : {"floor.config", "global_variance.json", "global_variance.csv", "Map.yaml", "Map.png",
                          "roomseg.png", "class_noise.csv", "category_meta.json"})
        EXPECT_TRUE(std::filesystem::exists(d + "/" + f)) << f;
    const char* bad[] = {"simp-import-map", "--simp-dir", "x"};
    ImportMapApp app2;
    EXPECT_THAT(errorOf([&] { app2.initialize(3, bad); }), HasSubstr("missing required option --out W"));
}

// ---- The authors' real map (skipped when ../shared/data/simp-office is absent). ----

TEST(SimpOffice, ImportMatchesThePublishedFiles) {
    if (!std::filesystem::exists(kOffice + "/global_variance.json"))
        GTEST_SKIP() << "simp-office data not found at " << kOffice << " (optional, read-only authors' data)";
    const World w = importSimpMap(kOffice);
    ASSERT_EQ(w.objects.objects.size(), 89u);
    ASSERT_EQ(w.objects.class_names.size(), 14u);
    EXPECT_EQ(w.floorplan.getSizeX(), 521u);
    EXPECT_EQ(w.floorplan.getSizeY(), 280u);
    EXPECT_FLOAT_EQ(w.floorplan.getResolution(), 0.05f);
    EXPECT_FLOAT_EQ(w.floorplan.getXMin(), -13.9155f);
    EXPECT_FLOAT_EQ(w.floorplan.getYMin(), -11.04537f);
    EXPECT_FLOAT_EQ(w.floorplan.getXMax(), static_cast<float>(-13.9155 + 521 * 0.05));

    const auto gv = readJson(kOffice + "/global_variance.json");
    std::map<int, int> published, imported;
    for (const auto& c : gv["category"]) ++published[c.get<int>()];
    for (const auto& o : w.objects.objects) ++imported[o.class_id];
    EXPECT_EQ(imported, published);

    // Footprints reproduce the published corners within half a pixel, and the noise means are
    // the published absolute pixels.
    const SimpPixelFrame px = frameOf(w);
    for (std::size_t i = 0; i < 89; ++i) {
        const MapObject& o = w.objects.objects[i];
        EXPECT_EQ(o.id, gv["uid"][i].get<long long>());
        EXPECT_LT(cornerDeviationPx(footprintPx(o, px), gv["corners"][i].get<std::vector<int>>()), 0.5) << "uid " << o.id;
        const Eigen::Matrix2d R = o.box.R.topLeftCorner<2, 2>();
        const Eigen::Vector2d mean_px = px.toPixel(o.box.center.head<2>() + R * o.noise->mean_m);
        EXPECT_NEAR(mean_px.x(), gv["mx"][i].get<double>(), 1e-4);
        EXPECT_NEAR(mean_px.y(), gv["my"][i].get<double>(), 1e-4);
        EXPECT_GT(o.room_id, 0) << "uid " << o.id;
        EXPECT_NEAR(o.box.center.z(), o.box.size.z() / 2, 1e-12);
    }
    // Room raster: 12 rooms, values 0..12, and the room names of floor.config.
    double max_id = 0;
    cv::minMaxLoc(w.rooms.ids, nullptr, &max_id);
    EXPECT_EQ(max_id, 12);
    EXPECT_EQ(w.objects.rooms.size(), 12u);
    // Map.png is trinary: walls + furniture occupied, corridors free.
    int occ = 0, fre = 0;
    for (unsigned y = 0; y < 280; ++y)
        for (unsigned x = 0; x < 521; ++x) {
            const float c = w.floorplan.getCell(x, y);
            occ += c < 0.01f;  // MRPT stores P(free)
            fre += c > 0.99f;
        }
    EXPECT_EQ(occ, 9043);   // pixels with value 0 in Map.png
    EXPECT_EQ(fre, 86921);  // pixels with value 255
}

TEST(SimpOffice, ImportExportImportRoundTrip) {
    if (!std::filesystem::exists(kOffice + "/global_variance.json"))
        GTEST_SKIP() << "simp-office data not found at " << kOffice << " (optional, read-only authors' data)";
    const std::string dir = freshDir();
    const World a = importSimpMap(kOffice);
    exportSimpMap(a, dir + "/exported");
    const auto src = readJson(kOffice + "/global_variance.json");
    const auto out = readJson(dir + "/exported/global_variance.json");
    ASSERT_EQ(out["uid"], src["uid"]);
    ASSERT_EQ(out["category"], src["category"]);
    // Every published corner is reproduced exactly (as a set; the starting corner may differ).
    for (std::size_t i = 0; i < 89; ++i) {
        std::vector<std::pair<int, int>> s, e;
        for (int k = 0; k < 4; ++k) {
            s.emplace_back(src["corners"][i][2 * k].get<int>(), src["corners"][i][2 * k + 1].get<int>());
            e.emplace_back(out["corners"][i][2 * k].get<int>(), out["corners"][i][2 * k + 1].get<int>());
        }
        std::sort(s.begin(), s.end());
        std::sort(e.begin(), e.end());
        EXPECT_EQ(s, e) << "uid " << src["uid"][i];
        EXPECT_NEAR(out["mx"][i].get<double>(), src["mx"][i].get<double>(), 1e-4);
        EXPECT_NEAR(out["my"][i].get<double>(), src["my"][i].get<double>(), 1e-4);
        EXPECT_NEAR(out["sx"][i].get<double>(), src["sx"][i].get<double>(), 1e-9);
        EXPECT_NEAR(out["sy"][i].get<double>(), src["sy"][i].get<double>(), 1e-9);
        EXPECT_EQ(out["b"][i].get<double>(), src["b"][i].get<double>());
    }
    const World b = importSimpMap(dir + "/exported");
    // Same input corners -> the same fit, up to float noise.
    expectSameWorld(a, b, 1e-9);
}
