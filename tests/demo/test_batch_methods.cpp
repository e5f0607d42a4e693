/// \file test_batch_methods.cpp
/// simp-eval batch's method list (libs/eval, below libs/localization) is the localizer's list of
/// sensor models: libs/maps' object models, then the LiDAR ones (libs/localization).
#include <gtest/gtest.h>
#include <simp/eval/BatchConfig.h>
#include <simp/localization/LocalizeOptions.h>

TEST(BatchMethods, AreTheLocalizerSensorModels) {
    EXPECT_EQ(simp::eval::batchMethodNames(), simp::localization::sensorModelNames());
    for (const auto& m : simp::eval::batchMethodNames()) EXPECT_NE(simp::eval::methodLabel(m), m) << "no paper label for " << m;
}
