/// Tests of the label generation (paper Sec. "Label Generation for 3D Object Detection") on a scene
/// made here: a camera at 1 m looking along world +x, a cabinet in front of a chair (occlusion; a
/// table would hide only with its top, camera/Occluders.h), a board half outside the image
/// (truncation), a chair behind a wall of the floor plan.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <simp/camera/ZBufferVisibility.h>
#include <simp/labels/LabelGenerator.h>
#include <simp/labels/LabelsApp.h>
#include <simp/detector_io/Omni3DBox.h>
#include <simp/world/World.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fs = std::filesystem;
using namespace simp;

namespace {

std::string outDir(const std::string& name) {
    const fs::path p = fs::path(SIMP_TEST_OUTPUT_DIR) / "labels" / name;
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

labels::PosedImage posedImage() {
    labels::PosedImage im;
    im.id = 7;
    im.file_path = "rgb/000007.png";
    im.camera.intrinsics = camera::makeIntrinsics(640, 480, 400, 400, 320, 240);
    Eigen::Matrix3d R;  // columns: camera x = world -y, camera y = world -z, camera z = world +x
    R << 0, 0, 1, -1, 0, 0, 0, -1, 0;
    im.camera.world_T_camera.linear() = R;
    im.camera.world_T_camera.translation() = Eigen::Vector3d(0, 0, 1);
    return im;
}

world::MapObject object(int id, int cls, const Eigen::Vector3d& c, const Eigen::Vector3d& size, double yaw) {
    world::MapObject o;
    o.id = id;
    o.class_id = cls;
    o.box = geometry::makeUprightBox(c, size, yaw);
    return o;
}

/// chair A (hidden by cabinet B), cabinet B, board C (centre on the left image border), chair D behind a wall.
world::World scene() {
    world::World w;
    w.objects.class_names = {"chair", "cabinet", "board"};
    w.objects.class_noise.assign(3, std::nullopt);
    w.objects.objects = {object(1, 0, {4.0, 0.0, 0.5}, {0.6, 0.6, 1.0}, 0.3),
                         object(2, 1, {3.0, 0.0, 0.5}, {0.8, 0.8, 1.0}, 0.0),
                         object(3, 2, {3.0, 2.4, 1.0}, {0.05, 1.0, 1.0}, 0.0),
                         object(4, 0, {8.0, -2.5, 0.5}, {0.6, 0.6, 1.0}, 0.0)};
    w.floorplan.setSize(-2.0, 12.0, -6.0, 6.0, 0.05, 1.0f);  // free everywhere (MRPT cell value = P(free))
    for (double y = -3.0; y <= 0.0; y += 0.025) w.floorplan.setCell(w.floorplan.x2idx(6.05), w.floorplan.y2idx(y), 0.0f);  // wall
    return w;
}

camera::ImageBox manualProjection(const labels::PosedImage& im, const geometry::Box3D& b) {
    camera::ImageBox out(1e9, 1e9, -1e9, -1e9);
    for (const auto& X : b.corners()) {
        const Eigen::Vector3d Xc = im.camera.world_T_camera.linear().transpose() * (X - im.camera.world_T_camera.translation());
        const Eigen::Vector3d x = im.camera.K() * Xc;
        out(0) = std::min(out(0), x.x() / x.z()), out(1) = std::min(out(1), x.y() / x.z());
        out(2) = std::max(out(2), x.x() / x.z()), out(3) = std::max(out(3), x.y() / x.z());
    }
    return out;
}

const labels::LabelAnnotation* annotationOf(const labels::LabelSet& s, std::int64_t object_id) {
    for (const auto& a : s.annotations)
        if (a.object_id == object_id) return &a;
    return nullptr;
}

std::vector<labels::Detection2D> detectionsFor(const world::World& w, const labels::PosedImage& im) {
    const auto pb = camera::projectBox(im.camera, w.objects.objects[1].box);
    const auto pc = camera::projectBox(im.camera, w.objects.objects[2].box);
    return {{7, "cabinet", pb.bbox_trunc(0) + 3, pb.bbox_trunc(1) - 2, pb.bbox_trunc(2) + 2, pb.bbox_trunc(3) - 4, 0.9},
            {7, "board", pc.bbox_trunc(0), pc.bbox_trunc(1), pc.bbox_trunc(2), pc.bbox_trunc(3), 0.8},
            {7, "cabinet", pc.bbox_trunc(0), pc.bbox_trunc(1), pc.bbox_trunc(2), pc.bbox_trunc(3), 0.7},  // wrong class
            {7, "chair", 600, 10, 630, 60, 0.6}};  // nothing there (a person, a closed door...)
}

}  // namespace

TEST(BoxProjection, ReprojectionAndTruncation) {
    const auto im = posedImage();
    const world::World w = scene();
    const auto& cabinet = w.objects.objects[1].box;
    const auto p = camera::projectBox(im.camera, cabinet);
    EXPECT_TRUE(p.visible_in_front);
    EXPECT_LT((p.bbox_proj - manualProjection(im, cabinet)).norm(), 1e-9);
    EXPECT_NEAR(p.truncation, 0.0, 1e-12);
    // Board centred on the left border: about half of its projected box is outside.
    const auto q = camera::projectBox(im.camera, w.objects.objects[2].box);
    EXPECT_LT(q.bbox_proj(0), 0.0);
    EXPECT_NEAR(q.truncation, 0.5, 0.03);
    // Behind the camera: nothing; across the camera plane: clipped at the near plane, still finite.
    EXPECT_FALSE(camera::projectBox(im.camera, geometry::makeUprightBox({-2, 0, 1}, {0.5, 0.5, 0.5}, 0)).visible_in_front);
    const auto r = camera::projectBox(im.camera, geometry::makeUprightBox({0.2, 0, 1}, {1.0, 0.5, 0.5}, 0));
    EXPECT_TRUE(r.visible_in_front);
    EXPECT_TRUE(r.bbox_proj.allFinite());
    EXPECT_GT(r.truncation, 0.5);
}

TEST(Visibility, BoxesAndWallsOcclude) {
    const auto im = posedImage();
    const world::World w = scene();
    std::vector<geometry::Box3D> boxes;
    for (const auto& o : w.objects.objects) boxes.push_back(o.box);
    const camera::FloorPlanGrid walls(w.floorplan);
    // As simp-labels renders: its pixel step, walls per pixel, no margin behind the wall face.
    camera::ZBufferParams p;
    p.downscale = labels::LabelOptions().visibility.pixel_step;
    p.wall_depth_margin_m = 0.0;
    p.max_distance_m = 30.0;
    p.walls_per_pixel = true;
    camera::ZBufferRenderer r;
    std::vector<camera::BoxView> with_walls, no_walls;
    r.render(im.camera, boxes, &walls, p, with_walls);
    EXPECT_LT(with_walls[0].visibleFraction(), 0.1) << "chair behind the cabinet";
    EXPECT_DOUBLE_EQ(with_walls[1].visibleFraction(), 1.0);
    EXPECT_DOUBLE_EQ(with_walls[2].visibleFraction(), 1.0);
    EXPECT_DOUBLE_EQ(with_walls[3].visibleFraction(), 0.0) << "chair behind the wall";
    r.render(im.camera, boxes, nullptr, p, no_walls);
    EXPECT_DOUBLE_EQ(no_walls[3].visibleFraction(), 1.0);
}

TEST(Visibility, DoorsHideNothing) {
    // An open door 2 m ahead in front of the cabinet (3 m): the labels see the cabinet through it, as
    // the simulator does (camera/Occluders.h); before, the door box hid the cabinet (visibility 0).
    const auto im = posedImage();
    world::World w = scene();
    w.objects.class_names.push_back("door");
    w.objects.class_noise.push_back(std::nullopt);
    w.objects.objects.push_back(object(5, 3, {2.0, 0.0, 1.0}, {0.05, 1.2, 2.0}, 0.0));
    labels::LabelOptions opts;
    opts.keep_unmatched = true;  // annotate every object in view, no 2D detections needed
    const labels::LabelSet s = labels::generateLabels(w.objects, &w.floorplan, {im}, {}, opts);
    const auto* cabinet = annotationOf(s, 2);
    const auto* door = annotationOf(s, 5);
    ASSERT_NE(cabinet, nullptr);
    ASSERT_NE(door, nullptr);
    EXPECT_DOUBLE_EQ(cabinet->visibility, 1.0);
    EXPECT_DOUBLE_EQ(door->visibility, 1.0);
    EXPECT_LT(annotationOf(s, 1)->visibility, 0.1) << "the chair is still behind the cabinet";
}

TEST(LabelsApp, OmniLabelsAgreeWithTheTruth) {
    const std::string d = outDir("scene");
    const world::World w = scene();
    world::saveWorld(w, d + "/world");
    const auto im = posedImage();
    labels::writeCameraFrames(d + "/frames.json", {im});
    std::ofstream csv(d + "/det.csv");
    csv << "image_id,class,x_min,y_min,x_max,y_max,score\n";
    csv.precision(17);
    for (const auto& x : detectionsFor(w, im))
        csv << x.image_id << ',' << x.class_name << ',' << x.x_min << ',' << x.y_min << ',' << x.x_max << ',' << x.y_max
            << ',' << x.score << '\n';
    csv.close();
    std::ofstream(d + "/keep.ini") << "[simp-labels]\nkeep_unmatched = true\nvisibility_pixel_step = 2\n";

    for (const bool keep : {false, true}) {
        std::vector<std::string> args = {"simp-labels", "--world", d + "/world", "--frames", d + "/frames.json",
                                         "--detections2d", d + "/det.csv", "--out", d + "/labels.json"};
        if (keep) args.insert(args.end(), {"--config", d + "/keep.ini"});
        std::vector<const char*> argv;
        for (const auto& a : args) argv.push_back(a.c_str());
        labels::LabelsApp app;
        std::ostringstream log;
        ASSERT_TRUE(app.initialize(static_cast<int>(argv.size()), argv.data(), log));
        ASSERT_EQ(app.run(log), 0);
        const labels::LabelSet& s = app.result;
        EXPECT_EQ(s.annotations.size(), keep ? 4u : 2u) << log.str();
        EXPECT_EQ(s.detections_unmatched, 2u);
        const auto* b = annotationOf(s, 2);
        const auto* c = annotationOf(s, 3);
        ASSERT_TRUE(b && c);
        ASSERT_TRUE(b->detection && c->detection);
        EXPECT_EQ(b->detection->class_name, "cabinet");
        EXPECT_LT((b->box_cam.center - Eigen::Vector3d(0, 0.5, 3.0)).norm(), 1e-12);
        EXPECT_LT((detector_io::omni3DDimensions(b->box_cam) - Eigen::Vector3d(0.8, 1.0, 0.8)).norm(), 1e-12);
        EXPECT_LT((detector_io::omni3DDimensions(c->box_cam) - Eigen::Vector3d(1.0, 1.0, 0.05)).norm(), 1e-12);
        EXPECT_LT((b->projection.bbox_proj - manualProjection(im, w.objects.objects[1].box)).norm(), 1e-9);
        EXPECT_NEAR(c->projection.truncation, 0.5, 0.03);
        EXPECT_DOUBLE_EQ(b->visibility, 1.0);
        if (keep) {
            EXPECT_LT(annotationOf(s, 1)->visibility, 0.1);
            EXPECT_DOUBLE_EQ(annotationOf(s, 4)->visibility, 0.0);
            EXPECT_FALSE(annotationOf(s, 1)->detection);
        }
    }
    // The file: Omni3D keys, corners in Omni3D order = the world corners seen from the camera.
    std::ifstream in(d + "/labels.json");
    const auto j = nlohmann::json::parse(in);
    ASSERT_EQ(j["images"].size(), 1u);
    EXPECT_EQ(j["images"][0]["file_path"], "rgb/000007.png");
    EXPECT_EQ(j["categories"][2]["name"], "board");
    const auto& a = j["annotations"][1];
    EXPECT_EQ(a["category_name"], "cabinet");
    for (const char* key : {"bbox2D_tight", "bbox2D_proj", "bbox2D_trunc", "bbox3D_cam", "center_cam", "dimensions", "R_cam",
                            "truncation", "visibility", "valid3D", "behind_camera"})
        EXPECT_TRUE(a.contains(key)) << key;
    const auto world_corners = w.objects.objects[1].box.corners();
    for (std::size_t v = 0; v < 8; ++v) {
        const Eigen::Vector3d p(a["bbox3D_cam"][v][0].get<double>(), a["bbox3D_cam"][v][1].get<double>(),
                                a["bbox3D_cam"][v][2].get<double>());
        const Eigen::Vector3d pw = im.camera.world_T_camera * p;
        double best = 1e9;
        for (const auto& cw : world_corners) best = std::min(best, (cw - pw).norm());
        EXPECT_LT(best, 1e-9) << "v" << v;
    }
    // Omni3D order: v0 -> v1 along local x (length L), v0 -> v3 along local y (down, length H), v0 -> v4 along z (W).
    const auto vtx = [&](std::size_t v) {
        return Eigen::Vector3d(a["bbox3D_cam"][v][0].get<double>(), a["bbox3D_cam"][v][1].get<double>(),
                               a["bbox3D_cam"][v][2].get<double>());
    };
    EXPECT_NEAR((vtx(1) - vtx(0)).norm(), 0.8, 1e-12);
    EXPECT_NEAR((vtx(3) - vtx(0)).y(), 1.0, 1e-12);  // camera y is down: v3 is below v0
    EXPECT_NEAR((vtx(4) - vtx(0)).norm(), 0.8, 1e-12);
}

TEST(LabelsBadInput, FilesAreNamed) {
    const std::string d = outDir("bad");
    const std::vector<std::string> names = {"chair", "table"};
    const auto err = [](auto f) -> std::string {
        try {
            f();
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    };
    std::ofstream(d + "/cols.csv") << "image_id,class,x_min,y_min,x_max,y_max,score\n1,chair,1,2,3\n";
    EXPECT_NE(err([&] { labels::readDetections2D(d + "/cols.csv", names); }).find("cols.csv: line 2: wrong column count 5"),
              std::string::npos);
    std::ofstream(d + "/cls.csv") << "1,sofa,1,2,3,4,0.5\n";
    EXPECT_NE(err([&] { labels::readDetections2D(d + "/cls.csv", names); }).find("cls.csv: line 1: unknown class 'sofa'"),
              std::string::npos);
    std::ofstream(d + "/num.csv") << "1,chair,1,two,3,4,0.5\n";
    EXPECT_NE(err([&] { labels::readDetections2D(d + "/num.csv", names); }).find("num.csv: line 1: column 4: expected a finite number"),
              std::string::npos);
    std::ofstream(d + "/frames.json") << R"({"images": [{"id": 1, "file_path": "a.png", "width": 640, "height": 480,
        "K": [[400, 0, 320], [0, 400, 240], [0, 0, 1]], "rotation": [[1,0,0],[0,1,0],[0,0,1]]}]})";
    EXPECT_NE(err([&] { labels::readCameraFrames(d + "/frames.json"); }).find("frames.json: images[0].position_m: missing key"),
              std::string::npos);
    EXPECT_NE(err([&] { labels::readCameraFrames(d + "/none.json"); }).find("none.json: file not found"), std::string::npos);
}

TEST(CameraFrames, PoseFromRobotPosesAndRig) {
    const std::string d = outDir("rig_frames");
    std::ofstream(d + "/rig.json") << R"({"cameras": [{"name": "FRONT", "x": 0.5, "y": 0, "z": 1, "yaw_rad": 0,
        "fx": 400, "fy": 400, "cx": 320, "cy": 240, "width": 640, "height": 480}]})";
    // Robot at x = t - 1 heading +x; at t = 0.5 it is at x = -0.5, the camera 0.5 m ahead at (0, 0, 1).
    io::writeTum(d + "/poses.tum", {{0.0, {-1.0, 0.0, 0.0}}, {1.0, {0.0, 0.0, 0.0}}});
    std::ofstream(d + "/frames.json") << R"({"images": [{"id": 7, "file_path": "a.png", "camera": "FRONT", "timestamp": 0.5}]})";
    const auto rig = detector_io::loadCameraRig(d + "/rig.json");
    const auto poses = io::readTum(d + "/poses.tum");
    const auto ims = labels::readCameraFrames(d + "/frames.json", &rig, &poses);
    ASSERT_EQ(ims.size(), 1u);
    const auto ref = posedImage();  // at (0, 0, 1) looking along +x
    EXPECT_LT((ims[0].camera.world_T_camera.matrix() - ref.camera.world_T_camera.matrix()).norm(), 1e-12);
    EXPECT_LT((ims[0].camera.K() - ref.camera.K()).norm(), 1e-12);
    EXPECT_EQ(ims[0].camera.widthPx(), 640);
    // Without rig and poses the same file is an error naming the key.
    try {
        labels::readCameraFrames(d + "/frames.json");
        FAIL() << "expected an error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("frames.json: images[0].camera: an image given by camera name needs --rig and --poses"),
                  std::string::npos)
            << e.what();
    }
}

TEST(LabelOptions, ExampleIniHoldsTheDefaults) {
    mrpt::config::CConfigFile cfg(std::string(SIMP_SOURCE_DIR) + "/tests/data/detector_io/simp-labels.ini");
    labels::LabelOptions o;
    o.iou_threshold = 0.9;
    o.keep_unmatched = true;
    o.visibility.pixel_step = 9;
    o.loadFromConfigFile(cfg, "simp-labels");
    EXPECT_DOUBLE_EQ(o.iou_threshold, 0.5);
    EXPECT_FALSE(o.keep_unmatched);
    EXPECT_EQ(o.visibility.pixel_step, 4);
    EXPECT_TRUE(o.visibility.ignore_object_cells);
}
