// objects.json: lossless round trip, every documented error, classId/noiseOf, default heights.
#include "TestUtil.h"

#include <gmock/gmock.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/world/ObjectMapData.h>

#include <cmath>

using namespace simp::world;
using simp_test::freshDir;
using simp_test::errorOf;
using simp_test::writeFile;
using ::testing::HasSubstr;

namespace {

ObjectMapData makeMap() {
    ObjectMapData d;
    d.class_names = simp::obs::defaultClassNames();
    d.class_noise.assign(d.class_names.size(), std::nullopt);
    simp::model::NoiseModel table;
    table.mean_m = {-0.072, 0.0488};
    table.cov_m2 << 0.1479, 0.0123, 0.0123, 0.6553;
    table.exponent_b = 4.0;
    d.class_noise[4] = table;
    for (int i = 0; i < 5; ++i) {
        MapObject o;
        o.id = 100 + i;
        o.class_id = (i % 2 == 0) ? 4 : 9;
        // Numbers without short decimal forms, to check full precision.
        o.box.center = {1.0 / 3.0 + i, -2.0 / 7.0, 0.375 + 1e-13 * i};
        o.box.size = {0.8 + M_PI * 1e-3, 1.7 / 3.0, 0.75};
        o.box.R = Eigen::AngleAxisd(0.1 * i + 1e-9, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                  Eigen::AngleAxisd(1e-3 * i, Eigen::Vector3d::UnitX()).toRotationMatrix();
        o.n_match = 3 + i;
        o.n_skip = i;
        o.room_id = i % 3;
        if (i == 1) {
            simp::model::NoiseModel n;
            n.mean_m = {0.01, -1.0 / 3.0};
            n.cov_m2 << 0.02, -0.001, -0.001, 0.05;
            o.noise = n;
        }
        d.objects.push_back(o);
    }
    d.rooms = {{1, "0", "office"}, {2, "1", "kitchen"}};
    d.room_categories = {"office", "corridor", "kitchen"};
    return d;
}

/// A valid file whose objects[3] is replaced by `object3` (JSON text).
std::string fileWithObject3(const std::string& object3) {
    const std::string ok = R"({"id": 1, "class": "table", "center_m": [0, 0, 0.4], "size_m": [1, 1, 0.8], "yaw_rad": 0})";
    return R"({"format": "simp-object-map", "version": 1, "classes": ["table", "chair"], "objects": [)" + ok + "," +
           ok.substr(0, 7) + "2" + ok.substr(8) + "," + ok.substr(0, 7) + "3" + ok.substr(8) + "," + object3 + "]}";
}

std::string loadError(const std::string& text) {
    const std::string path = freshDir() + "/objects.json";
    writeFile(path, text);
    return errorOf([&] { loadObjectMap(path); });
}

}  // namespace

TEST(ObjectMapJson, RoundTripIsLossless) {
    const ObjectMapData d = makeMap();
    const std::string path = freshDir() + "/objects.json";
    saveObjectMap(d, path);
    const ObjectMapData r = loadObjectMap(path);
    ASSERT_EQ(r.class_names, d.class_names);
    ASSERT_EQ(r.class_noise.size(), d.class_noise.size());
    for (std::size_t c = 0; c < d.class_noise.size(); ++c) {
        ASSERT_EQ(r.class_noise[c].has_value(), d.class_noise[c].has_value()) << c;
        if (d.class_noise[c]) {
            EXPECT_EQ(r.class_noise[c]->mean_m, d.class_noise[c]->mean_m);
            EXPECT_EQ(r.class_noise[c]->cov_m2, d.class_noise[c]->cov_m2);
            EXPECT_EQ(r.class_noise[c]->exponent_b, d.class_noise[c]->exponent_b);
        }
    }
    ASSERT_EQ(r.objects.size(), d.objects.size());
    for (std::size_t i = 0; i < d.objects.size(); ++i) {
        const MapObject &a = d.objects[i], &b = r.objects[i];
        EXPECT_EQ(b.id, a.id);
        EXPECT_EQ(b.class_id, a.class_id);
        EXPECT_EQ(b.box.center, a.box.center);  // bit-exact: doubles printed with full precision
        EXPECT_EQ(b.box.size, a.box.size);
        EXPECT_EQ(b.box.R, a.box.R);
        EXPECT_EQ(b.n_match, a.n_match);
        EXPECT_EQ(b.n_skip, a.n_skip);
        EXPECT_EQ(b.room_id, a.room_id);
        ASSERT_EQ(b.noise.has_value(), a.noise.has_value());
        if (a.noise) {
            EXPECT_EQ(b.noise->mean_m, a.noise->mean_m);
            EXPECT_EQ(b.noise->cov_m2, a.noise->cov_m2);
        }
    }
    ASSERT_EQ(r.rooms.size(), 2u);
    EXPECT_EQ(r.rooms[1].category, "kitchen");
    EXPECT_EQ(r.room_categories, d.room_categories);
}

TEST(ObjectMapJson, YawRadGivesAnUprightBoxAndOptionalCountersDefault) {
    const std::string path = freshDir() + "/objects.json";
    writeFile(path, R"({"format": "simp-object-map", "version": 1, "classes": ["desk"],
        "objects": [{"id": 7, "class": "desk", "center_m": [1, 2, 0.375], "size_m": [1.6, 0.8, 0.75], "yaw_rad": 0.5}]})");
    const ObjectMapData d = loadObjectMap(path);
    ASSERT_EQ(d.objects.size(), 1u);
    EXPECT_NEAR(std::atan2(d.objects[0].box.R(1, 0), d.objects[0].box.R(0, 0)), 0.5, 1e-15);
    EXPECT_EQ(d.objects[0].n_match, 1);
    EXPECT_EQ(d.objects[0].n_skip, 0);
    EXPECT_EQ(d.objects[0].room_id, 0);
    EXPECT_FALSE(d.objects[0].noise.has_value());
    EXPECT_FALSE(d.noiseOf(d.objects[0]).has_value());
}

TEST(ObjectMapJson, MissingFile) {
    EXPECT_THAT(errorOf([] { loadObjectMap("/nonexistent/objects.json"); }),
                HasSubstr("/nonexistent/objects.json: file not found"));
}

TEST(ObjectMapJson, InvalidJson) {
    EXPECT_THAT(loadError(R"({"format": "simp-object-map", )"), HasSubstr("objects.json: invalid JSON"));
}

TEST(ObjectMapJson, MissingFormatKey) {
    EXPECT_THAT(loadError(R"({"version": 1, "classes": ["a"], "objects": []})"), HasSubstr("objects.json: format: missing"));
}

TEST(ObjectMapJson, WrongFormatName) {
    EXPECT_THAT(loadError(R"({"format": "other", "version": 1, "classes": ["a"], "objects": []})"),
                HasSubstr("objects.json: format: expected \"simp-object-map\""));
}

TEST(ObjectMapJson, UnknownVersion) {
    EXPECT_THAT(loadError(R"({"format": "simp-object-map", "version": 2, "classes": ["a"], "objects": []})"),
                HasSubstr("objects.json: version: unsupported version 2 (this build reads version 1)"));
}

TEST(ObjectMapJson, MissingClasses) {
    EXPECT_THAT(loadError(R"({"format": "simp-object-map", "version": 1, "objects": []})"),
                HasSubstr("objects.json: classes: missing"));
}

TEST(ObjectMapJson, MissingObjects) {
    EXPECT_THAT(loadError(R"({"format": "simp-object-map", "version": 1, "classes": ["a"]})"),
                HasSubstr("objects.json: objects: missing"));
}

TEST(ObjectMapJson, EmptyObjectListIsValid) {
    const std::string path = freshDir() + "/objects.json";
    writeFile(path, R"({"format": "simp-object-map", "version": 1, "classes": ["a"], "objects": []})");
    EXPECT_TRUE(loadObjectMap(path).objects.empty());
}

TEST(ObjectMapJson, NegativeSizeNamesObjectIndexAndKey) {
    EXPECT_THAT(loadError(fileWithObject3(
                    R"({"id": 4, "class": "table", "center_m": [0, 0, 0.4], "size_m": [1, -1, 0.8], "yaw_rad": 0})")),
                HasSubstr("objects.json: objects[3].size_m: expected 3 positive numbers"));
}

TEST(ObjectMapJson, ShortSizeNamesObjectIndexAndKey) {
    EXPECT_THAT(loadError(fileWithObject3(
                    R"({"id": 4, "class": "table", "center_m": [0, 0, 0.4], "size_m": [1, 1], "yaw_rad": 0})")),
                HasSubstr("objects.json: objects[3].size_m: expected 3 positive numbers"));
}

TEST(ObjectMapJson, MissingCenter) {
    EXPECT_THAT(loadError(fileWithObject3(R"({"id": 4, "class": "table", "size_m": [1, 1, 1], "yaw_rad": 0})")),
                HasSubstr("objects.json: objects[3].center_m: missing"));
}

TEST(ObjectMapJson, NonNumericCenter) {
    EXPECT_THAT(loadError(fileWithObject3(
                    R"({"id": 4, "class": "table", "center_m": [0, "x", 0], "size_m": [1, 1, 1], "yaw_rad": 0})")),
                HasSubstr("objects.json: objects[3].center_m: expected 3 finite numbers"));
}

TEST(ObjectMapJson, UnknownClassIsNamed) {
    EXPECT_THAT(loadError(fileWithObject3(
                    R"({"id": 4, "class": "piano", "center_m": [0, 0, 0.4], "size_m": [1, 1, 0.8], "yaw_rad": 0})")),
                HasSubstr("objects.json: objects[3].class: unknown class 'piano'"));
}

TEST(ObjectMapJson, DuplicateId) {
    EXPECT_THAT(loadError(fileWithObject3(
                    R"({"id": 2, "class": "table", "center_m": [0, 0, 0.4], "size_m": [1, 1, 0.8], "yaw_rad": 0})")),
                HasSubstr("objects.json: objects[3].id: duplicate id 2"));
}

TEST(ObjectMapJson, RotationNotOrthonormal) {
    EXPECT_THAT(loadError(fileWithObject3(R"({"id": 4, "class": "table", "center_m": [0, 0, 0.4], "size_m": [1, 1, 0.8],
        "rotation": [[1, 0, 0], [0, 2, 0], [0, 0, 1]]})")),
                HasSubstr("objects.json: objects[3].rotation: not a rotation matrix"));
}

TEST(ObjectMapJson, RotationAndYawTogether) {
    EXPECT_THAT(loadError(fileWithObject3(R"({"id": 4, "class": "table", "center_m": [0, 0, 0.4], "size_m": [1, 1, 0.8],
        "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "yaw_rad": 0})")),
                HasSubstr("objects.json: objects[3].rotation: expected exactly one of"));
}

TEST(ObjectMapJson, NegativeCounter) {
    EXPECT_THAT(loadError(fileWithObject3(
                    R"({"id": 4, "class": "table", "center_m": [0, 0, 0.4], "size_m": [1, 1, 0.8], "yaw_rad": 0, "n_skip": -1})")),
                HasSubstr("objects.json: objects[3].n_skip: expected an integer >= 0"));
}

TEST(ObjectMapJson, ObjectNoiseNotPositiveDefinite) {
    EXPECT_THAT(loadError(fileWithObject3(R"({"id": 4, "class": "table", "center_m": [0, 0, 0.4], "size_m": [1, 1, 0.8],
        "yaw_rad": 0, "noise": {"mean_m": [0, 0], "cov_m2": [[1, 2], [2, 1]], "b": 2}})")),
                HasSubstr("objects.json: objects[3].noise: invalid noise model"));
}

TEST(ObjectMapJson, ClassNoiseForUnknownClass) {
    EXPECT_THAT(loadError(R"({"format": "simp-object-map", "version": 1, "classes": ["a"], "objects": [],
        "class_noise": {"b": {"mean_m": [0, 0], "cov_m2": [[1, 0], [0, 1]], "b": 2}}})"),
                HasSubstr("objects.json: class_noise.b: unknown class 'b'"));
}

TEST(ObjectMapJson, ClassNoiseMissingCovariance) {
    EXPECT_THAT(loadError(R"({"format": "simp-object-map", "version": 1, "classes": ["a"], "objects": [],
        "class_noise": {"a": {"mean_m": [0, 0], "b": 2}}})"),
                HasSubstr("objects.json: class_noise.a.cov_m2: missing"));
}

TEST(ObjectMapJson, SaveRejectsInvalidContent) {
    ObjectMapData d = makeMap();
    d.objects[2].box.size.y() = std::nan("");
    const std::string path = freshDir() + "/objects.json";
    EXPECT_THAT(errorOf([&] { saveObjectMap(d, path); }), HasSubstr("objects.json: objects[2].size_m"));
}

TEST(ObjectMapData, ClassIdAndNoiseOf) {
    const ObjectMapData d = makeMap();
    EXPECT_EQ(d.classId("table"), 4);
    EXPECT_EQ(d.classId("desk"), 13);
    EXPECT_EQ(d.classId("piano"), -1);
    // Object 0 (table, no own noise) -> the class's; object 1 (cabinet, own) -> its own;
    // object 3 (cabinet, none, class not modelled) -> nothing.
    ASSERT_TRUE(d.noiseOf(d.objects[0]).has_value());
    EXPECT_EQ(d.noiseOf(d.objects[0])->exponent_b, 4.0);
    ASSERT_TRUE(d.noiseOf(d.objects[1]).has_value());
    EXPECT_DOUBLE_EQ(d.noiseOf(d.objects[1])->mean_m.y(), -1.0 / 3.0);
    EXPECT_FALSE(d.noiseOf(d.objects[3]).has_value());
}

TEST(DefaultClassHeight, AllPaperClassesRealisticAndUnknownThrows) {
    for (const auto& name : simp::obs::defaultClassNames()) {
        const double h = defaultClassHeight(name);
        EXPECT_GT(h, 0.3) << name;
        EXPECT_LT(h, 2.2) << name;
    }
    EXPECT_DOUBLE_EQ(defaultClassHeight("door"), 2.0);
    EXPECT_DOUBLE_EQ(defaultClassHeight("table"), 0.75);
    EXPECT_DOUBLE_EQ(defaultClassHeight("person"), 1.7);
    EXPECT_THAT(errorOf([] { defaultClassHeight("piano"); }), HasSubstr("'piano'"));
}
