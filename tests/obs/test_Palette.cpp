// The one palette (simp/obs/Palette.h): classes by name, a fixed fallback, distinct role colours.
#include <gtest/gtest.h>
#include <simp/obs/ObjectClasses.h>
#include <simp/obs/Palette.h>

#include <algorithm>
#include <set>

using namespace simp::obs;

TEST(Palette, TheDetectorsClassesHaveFourteenColours) {
    std::set<Rgb> seen;
    for (const auto& name : defaultClassNames()) seen.insert(classColorRgb(name));
    EXPECT_EQ(seen.size(), 14u);
    // the first ones as the 3D views always had them (Tableau 10 in list order)
    EXPECT_EQ(classColorRgb("sink"), (Rgb{31, 119, 180}));
    EXPECT_EQ(classColorRgb("door"), (Rgb{255, 127, 14}));
}

TEST(Palette, ByNameNotById) {
    EXPECT_EQ(canonicalClassName("  Fire_Extinguisher "), "fire extinguisher");
    EXPECT_EQ(classColorRgb("fire-extinguisher"), classColorRgb("fire extinguisher"));
    EXPECT_EQ(classColorRgb(0, {"chair", "sink"}), classColorRgb("chair"));
    EXPECT_EQ(classColorRgb(1, {"chair", "sink"}), classColorRgb(0));  // sink is 0 of the detector's list
    EXPECT_EQ(classColorRgb(-3, {"chair"}), classColorRgb("class -3"));
}

TEST(Palette, UnknownNamesAreDeterministicAndNoDetectorColour) {
    std::set<Rgb> detector;
    for (const auto& name : defaultClassNames()) detector.insert(classColorRgb(name));
    for (const char* name : {"forklift", "bin", "printer", "plant pot", "monitor", ""}) {
        const Rgb c = classColorRgb(name);
        EXPECT_EQ(c, classColorRgb(name));
        EXPECT_EQ(detector.count(c), 0u) << name;
        EXPECT_NE(std::find(kFallbackClassColors.begin(), kFallbackClassColors.end(), c), kFallbackClassColors.end());
    }
}

TEST(Palette, WhatIsDrawnOverClassesHasNoClassColour) {
    std::set<Rgb> classes;
    for (const auto& name : defaultClassNames()) classes.insert(classColorRgb(name));
    for (const auto& c : kFallbackClassColors) classes.insert(c);
    namespace fc = figure_colors;
    for (const Rgb& role : {fc::kGroundTruth, fc::kEstimate, fc::kParticles, fc::kKidnapLifted, fc::kKidnapPutDown})
        EXPECT_EQ(classes.count(role), 0u);
}
