/// Doors are seen but hide nothing in the occlusion renderer (z-buffer); other boxes and walls hide
/// what lies behind them, with walls cast per column or along every pixel's own ray.
#include <gtest/gtest.h>
#include <simp/camera/Occluders.h>
#include <simp/camera/ZBufferVisibility.h>
#include <simp/obs/CObservationObjects3D.h>

using namespace simp::camera;
using simp::geometry::makeUprightBox;

namespace {

/// A camera 0.63 m high at the origin looking along world +x.
PinholeCamera forwardCamera() {
    return PinholeCamera::onRobot(mrpt::math::TPose2D(0, 0, 0), simp::obs::cameraPoseOnRobot(0, 0, 0.63, 0),
                                  defaultIntrinsics());
}

/// An open door 2 m ahead (0.9 m wide, 2 m high, 5 cm thick) and a cabinet right behind it.
const std::vector<simp::geometry::Box3D> kDoorAndCabinet{makeUprightBox({2.0, 0, 1.0}, {0.05, 0.9, 2.0}, 0.0),
                                                         makeUprightBox({3.5, 0, 0.5}, {0.5, 0.5, 1.0}, 0.0)};

/// A 6 m x 6 m free floor with a wall across x in [3.0, 3.1) for y below `wall_end_y`.
FloorPlanGrid wallUpTo(double wall_end_y) {
    mrpt::maps::COccupancyGridMap2D g(-1, 5, -3, 3, 0.1f);
    g.fill(1.0f);
    for (int cy = 0; cy < g.y2idx(wall_end_y); ++cy) g.setCell(g.x2idx(3.05), cy, 0.0f);
    return FloorPlanGrid(g);
}

/// The views of `boxes` with the walls cast per column (first) and per pixel (second).
std::pair<std::vector<BoxView>, std::vector<BoxView>> perColumnAndPerPixel(const PinholeCamera& camera,
                                                                           const std::vector<simp::geometry::Box3D>& boxes,
                                                                           const FloorPlanGrid& walls, ZBufferParams p) {
    ZBufferRenderer r;
    std::pair<std::vector<BoxView>, std::vector<BoxView>> out;
    p.walls_per_pixel = false;
    r.render(camera, boxes, &walls, p, out.first);
    p.walls_per_pixel = true;
    r.render(camera, boxes, &walls, p, out.second);
    return out;
}

}  // namespace

TEST(Occluders, OnlyDoorsAreSeeThroughAndOnlyTablesOpenBelow) {
    EXPECT_FALSE(occludes("door"));
    EXPECT_TRUE(occludes("cabinet"));
    EXPECT_TRUE(occludes("table"));
    EXPECT_TRUE(occludes(""));
    EXPECT_EQ(occlusionOf("table"), kOpenBelow);
    EXPECT_EQ(occlusionOf("desk"), kSolid);
    EXPECT_EQ(occludingClasses({"sink", "door", "chair", "table"}), (std::vector<char>{1, 0, 1, 2}));
    const std::vector<char> kinds = occludingClasses({"door", "table"});
    EXPECT_EQ(occlusionOfClassId(kinds, 0), kSeeThrough);
    EXPECT_EQ(occlusionOfClassId(kinds, 1), kOpenBelow);
    EXPECT_EQ(occlusionOfClassId(kinds, 2), kSolid);   // an id outside the list is solid
    EXPECT_EQ(occlusionOfClassId(kinds, -1), kSolid);
}

TEST(Occluders, ZBufferSeesDrawersUnderATableAndHidesBehindItsTop) {
    // A 0.75 m table 2 m ahead of the 0.63 m camera; drawers (0.6 m) under it, and a tall cabinet
    // behind it. Solid, the table hides the drawers completely; open below, the drawers are seen
    // whole (the camera is below the top), the cabinet is hidden only where the top is in front,
    // and the table itself is as visible as a solid one.
    const std::vector<simp::geometry::Box3D> boxes{makeUprightBox({2.0, 0, 0.375}, {0.8, 1.6, 0.75}, 0.0),
                                                   makeUprightBox({2.0, 0.3, 0.3}, {0.5, 0.4, 0.6}, 0.0),
                                                   makeUprightBox({3.5, 0, 0.9}, {0.5, 0.8, 1.8}, 0.0)};
    ZBufferParams p;
    p.downscale = 2;
    ZBufferRenderer r;
    std::vector<BoxView> solid, open;
    const std::vector<char> all_solid{kSolid, kSolid, kSolid}, table_open{kOpenBelow, kSolid, kSolid};
    p.occludes = &all_solid;
    r.render(forwardCamera(), boxes, nullptr, p, solid);
    p.occludes = &table_open;
    r.render(forwardCamera(), boxes, nullptr, p, open);
    ASSERT_GT(solid[1].covered_px, 100);
    EXPECT_EQ(solid[1].visible_px, 0);
    EXPECT_EQ(open[1].visible_px, open[1].covered_px);
    EXPECT_EQ(open[0].visible_px, solid[0].visible_px);
    EXPECT_EQ(open[0].covered_px, solid[0].covered_px);
    // The cabinet: hidden by the whole table's silhouette when solid, by the top only when open.
    EXPECT_GT(open[2].visible_px, solid[2].visible_px);
    EXPECT_LT(open[2].visible_px, open[2].covered_px);
    // The top hides what is behind it at its height: a box on the table's far side at 0.7 m.
    const std::vector<simp::geometry::Box3D> behind_top{boxes[0], makeUprightBox({3.0, 0, 0.7}, {0.2, 0.2, 0.08}, 0.0)};
    const std::vector<char> occ{kOpenBelow, kSolid};
    p.occludes = &occ;
    std::vector<BoxView> v;
    r.render(forwardCamera(), behind_top, nullptr, p, v);
    ASSERT_GT(v[1].covered_px, 0);
    EXPECT_EQ(v[1].visible_px, 0);
}

TEST(Occluders, ZBufferSeesThroughADoor) {
    ZBufferRenderer r;
    std::vector<BoxView> solid, see_through;
    ZBufferParams p;
    r.render(forwardCamera(), kDoorAndCabinet, nullptr, p, solid);
    ASSERT_GT(solid[1].covered_px, 20);
    EXPECT_EQ(solid[1].visible_px, 0);  // the door box hides the cabinet completely
    const std::vector<char> occ{0, 1};
    p.occludes = &occ;
    r.render(forwardCamera(), kDoorAndCabinet, nullptr, p, see_through);
    EXPECT_EQ(see_through[1].visible_px, see_through[1].covered_px);  // the cabinet is fully visible
    EXPECT_EQ(see_through[0].visible_px, see_through[0].covered_px);  // the door is seen (nothing in front)
    EXPECT_EQ(see_through[0].covered_px, solid[0].covered_px);
}

TEST(Occluders, ZBufferHidesADoorBehindACabinet) {
    // Swapped: a cabinet in front of the door still hides part of the door.
    const std::vector<simp::geometry::Box3D> boxes{makeUprightBox({3.0, 0, 1.0}, {0.05, 0.9, 2.0}, 0.0),
                                                   makeUprightBox({1.5, 0, 0.5}, {0.5, 0.5, 1.0}, 0.0)};
    const std::vector<char> occ{0, 1};
    ZBufferParams p;
    p.occludes = &occ;
    ZBufferRenderer r;
    std::vector<BoxView> v;
    r.render(forwardCamera(), boxes, nullptr, p, v);
    EXPECT_GT(v[0].occludedFraction(), 0.2);
    EXPECT_LT(v[0].occludedFraction(), 0.9);
    EXPECT_EQ(v[1].visible_px, v[1].covered_px);
}

TEST(Occluders, WallsPerPixelFollowARolledCamera) {
    // A wall on the right half (y < 0, x in [3.0, 3.1)), the camera 0.3 m left of it and rolled 90
    // deg about its optical axis: image columns are horizontal in the world. Per column, the walls
    // are cast along each column's ray at the principal row, all straight ahead past the wall's end,
    // so the box behind the wall shows; along every pixel's own ray it is hidden, and the box
    // behind the open half stays seen both ways.
    const FloorPlanGrid walls = wallUpTo(0.0);
    PinholeCamera rolled = PinholeCamera::onRobot(mrpt::math::TPose2D(0, 0.3, 0), simp::obs::cameraPoseOnRobot(0, 0, 0.63, 0),
                                                  defaultIntrinsics());
    rolled.world_T_camera.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
    const std::vector<simp::geometry::Box3D> boxes{makeUprightBox({4.0, -0.6, 0.6}, {0.4, 0.4, 0.4}, 0.0),
                                                   makeUprightBox({4.0, 1.2, 0.6}, {0.4, 0.4, 0.4}, 0.0)};
    ZBufferParams p;
    p.wall_depth_margin_m = 0.0;
    const auto [per_column, per_pixel] = perColumnAndPerPixel(rolled, boxes, walls, p);
    ASSERT_GT(per_pixel[0].covered_px, 10);
    ASSERT_GT(per_pixel[1].covered_px, 10);
    EXPECT_EQ(per_pixel[0].visible_px, 0);
    EXPECT_EQ(per_pixel[1].visible_px, per_pixel[1].covered_px);
    EXPECT_EQ(per_column[0].visible_px, per_column[0].covered_px);  // what the column approximation misses
    EXPECT_EQ(per_column[1].visible_px, per_column[1].covered_px);
}

TEST(Occluders, WallsPerPixelEqualWallsPerColumnForALevelCamera) {
    const FloorPlanGrid walls = wallUpTo(0.2);
    const std::vector<simp::geometry::Box3D> boxes{makeUprightBox({4.0, -0.8, 0.6}, {0.4, 0.8, 1.2}, 0.3),
                                                   makeUprightBox({3.5, 0.4, 0.5}, {0.5, 0.5, 1.0}, 0.0),
                                                   makeUprightBox({2.0, -0.2, 0.3}, {0.3, 0.3, 0.6}, 0.0)};
    const auto [per_column, per_pixel] = perColumnAndPerPixel(forwardCamera(), boxes, walls, ZBufferParams{});
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        ASSERT_GT(per_pixel[k].covered_px, 0) << k;
        EXPECT_EQ(per_pixel[k].covered_px, per_column[k].covered_px) << k;
        EXPECT_EQ(per_pixel[k].unwalled_px, per_column[k].unwalled_px) << k;
        EXPECT_EQ(per_pixel[k].visible_px, per_column[k].visible_px) << k;
    }
    EXPECT_LT(per_pixel[0].unwalled_px, per_pixel[0].covered_px);  // the wall does hide something
}

TEST(Occluders, WallsStillOccludeBehindADoorGap) {
    // A wall at x in [3.0, 3.1) across the view: the cabinet at x = 3.5 stays hidden even with the
    // door see-through (a closed doorway is a wall of the floor plan, not a door box).
    mrpt::maps::COccupancyGridMap2D g(-1, 5, -3, 3, 0.1f);
    g.fill(1.0f);
    for (int cy = 0; cy < static_cast<int>(g.getSizeY()); ++cy) g.setCell(g.x2idx(3.05), cy, 0.0f);
    const FloorPlanGrid walls(g);
    const std::vector<char> occ{0, 1};
    ZBufferParams p;
    p.occludes = &occ;
    p.wall_depth_margin_m = 0.0;
    ZBufferRenderer r;
    std::vector<BoxView> v;
    r.render(forwardCamera(), kDoorAndCabinet, &walls, p, v);
    EXPECT_EQ(v[1].unwalled_px, 0);
    EXPECT_EQ(v[1].visible_px, 0);
    EXPECT_EQ(v[0].visible_px, v[0].covered_px);
}

TEST(Occluders, ZBufferUnhiddenByIsOneWay) {
    // A cabinet 1.5 m ahead hides one of the same size 2.5 m ahead; with unhidden_by = {0} for the
    // far one, the near one no longer hides it (counted in unhidden_px), and it still hides nothing
    // for the near one. A map update's possible new place in front of the old (DisplacedCopies.h).
    const std::vector<simp::geometry::Box3D> boxes{makeUprightBox({1.5, 0, 0.9}, {0.5, 1.0, 1.8}, 0.0),
                                                   makeUprightBox({2.5, 0, 0.9}, {0.5, 1.0, 1.8}, 0.0)};
    ZBufferRenderer r;
    ZBufferParams p;
    std::vector<BoxView> plain, unhidden;
    r.render(forwardCamera(), boxes, nullptr, p, plain);
    ASSERT_GT(plain[1].covered_px, 20);
    EXPECT_EQ(plain[1].visible_px, 0);
    const std::vector<std::vector<int>> by{{}, {0}};
    p.unhidden_by = &by;
    r.render(forwardCamera(), boxes, nullptr, p, unhidden);
    EXPECT_EQ(unhidden[1].visible_px, unhidden[1].covered_px);
    EXPECT_EQ(unhidden[1].unhidden_px, unhidden[1].covered_px);
    EXPECT_NEAR(unhidden[1].occludedFractionByAll(), 1.0, 1e-12);
    EXPECT_EQ(unhidden[0].visible_px, plain[0].visible_px);
    EXPECT_EQ(unhidden[0].unhidden_px, 0);
}

TEST(Occluders, AHugeImageIsRenderedWithinTheBufferBound) {
    // A camera whose image (60000 x 45000 px, the same field of view) would need 2.7e9 z-buffer
    // pixels at downscale 1: rendered coarser, within kMaxRenderedPixels, with the same answer.
    PinholeCamera huge = forwardCamera();
    const double k = 60000.0 / huge.widthPx();
    huge.intrinsics.ncols = 60000;
    huge.intrinsics.nrows = 45000;
    huge.intrinsics.setIntrinsicParamsFromValues(huge.fx() * k, huge.fy() * k, huge.cx() * k, huge.cy() * k);
    ZBufferParams p;
    p.downscale = 1;
    const std::vector<char> occ{0, 1};
    p.occludes = &occ;
    ZBufferRenderer r;
    std::vector<BoxView> v;
    r.render(huge, kDoorAndCabinet, nullptr, p, v);
    ASSERT_GT(v[1].covered_px, 0);
    EXPECT_LE(v[0].covered_px, kMaxRenderedPixels);
    EXPECT_EQ(v[1].visible_px, v[1].covered_px);  // the door hides nothing, as at any size
}
