// The frame of a noise model on the ground (R_o of Eq. shiftdist).
#include <gtest/gtest.h>
#include <simp/model/NoiseFrame.h>

#include <cmath>

namespace simp::model {
namespace {

TEST(NoiseFrame, ClassFrameHasItsYAlongTheLongerSide) {
    // Longer side along the box x: the frame is turned by +90 deg.
    const auto board = geometry::makeUprightBox({2.0, 1.0, 1.2}, {1.6, 0.05, 1.0}, 0.2);
    EXPECT_NEAR(classNoiseFrameYaw(board), 0.2 + M_PI / 2, 1e-12);
    // The same solid with its axes relabelled (x and y swapped): the same frame up to a half turn.
    const auto same = geometry::makeUprightBox({2.0, 1.0, 1.2}, {0.05, 1.6, 1.0}, 0.2 + M_PI / 2);
    EXPECT_NEAR(std::remainder(classNoiseFrameYaw(same) - (0.2 + M_PI / 2), M_PI), 0.0, 1e-12);
    // Longer side along y, or a square footprint: the box frame.
    EXPECT_NEAR(classNoiseFrameYaw(geometry::makeUprightBox({0, 0, 0.5}, {0.5, 1.0, 1}, -0.4)), -0.4, 1e-12);
    EXPECT_NEAR(classNoiseFrameYaw(geometry::makeUprightBox({0, 0, 0.5}, {1, 1, 1}, 0.3)), 0.3, 1e-12);
}

TEST(NoiseFrame, AnObjectsOwnNoiseUsesTheBoxFrame) {
    const auto board = geometry::makeUprightBox({2.0, 1.0, 1.2}, {1.6, 0.05, 1.0}, 0.2);
    EXPECT_NEAR(noiseFrameYaw(board, NoiseSource::Object), 0.2, 1e-12);
    EXPECT_NEAR(noiseFrameYaw(board, NoiseSource::Class), 0.2 + M_PI / 2, 1e-12);
}

}  // namespace
}  // namespace simp::model
