/// \file test_LocalizationMethods.cpp
/// The one table of localization methods: names and labels unique, every object sensor model named
/// exactly once (by the method that runs it alone) and parsed back.
#include <gtest/gtest.h>
#include <simp/model/LocalizationMethods.h>

#include "common/ErrorOf.h"

#include <set>
#include <string>

using namespace simp::model;

TEST(LocalizationMethods, NamesAndLabelsAreUniqueAndFound) {
    std::set<std::string> names, labels;
    for (const auto& m : localizationMethods()) {
        EXPECT_TRUE(names.insert(m.name).second) << m.name;
        EXPECT_TRUE(labels.insert(m.label).second) << m.label;
        EXPECT_TRUE(m.object_model || m.uses_scans) << m.name << " weighs nothing";
        EXPECT_EQ(findLocalizationMethod(m.name), &m);
    }
    EXPECT_EQ(localizationMethodNames().size(), localizationMethods().size());
    EXPECT_EQ(findLocalizationMethod("SIMP"), nullptr);  // --method is exact
}

TEST(LocalizationMethods, EveryObjectModelHasOneName) {
    // The order is the one of the error messages and the documentation tables.
    EXPECT_EQ(sensorModelTypeNames(), (std::vector<std::string>{"simp", "edt", "d", "o"}));
    for (const auto type : {SensorModelType::Simp, SensorModelType::Edt, SensorModelType::D, SensorModelType::O}) {
        const std::string name = toString(type);
        EXPECT_NE(name, "?");
        EXPECT_EQ(parseSensorModelType(name), type) << name;
        EXPECT_EQ(findLocalizationMethod(name)->object_model, type) << name;
    }
    EXPECT_EQ(parseSensorModelType("EdT"), SensorModelType::Edt);  // the .ini key is case-insensitive
}

TEST(LocalizationMethods, AnUnknownObjectModelNamesTheValidOnes) {
    EXPECT_EQ(simp_test::errorOf([] { parseSensorModelType("lidar"); }),
              "unknown sensor model 'lidar' (valid: simp, edt, d, o)");
}
