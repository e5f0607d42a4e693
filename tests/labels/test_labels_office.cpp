/// simp-labels on the authors' real office floor (read-only, optional): the ground-truth floor plan
/// draws furniture footprints as occupied, so the walls must ignore the cells under the
/// objects (visibility_ignore_object_cells), or every object would hide itself.
#include <gtest/gtest.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/camera/ZBufferVisibility.h>
#include <simp/labels/CameraFrames.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/world/SimpFormat.h>

#include <cmath>
#include <filesystem>

using namespace simp;

namespace {

const std::string kOffice = std::string(SIMP_SHARED_DATA_DIR) + "/simp-office";

bool freeCell(const mrpt::maps::COccupancyGridMap2D& g, double x, double y) {
    const int cx = g.x2idx(x), cy = g.y2idx(y);
    return cx >= 0 && cy >= 0 && cx < static_cast<int>(g.getSizeX()) && cy < static_cast<int>(g.getSizeY()) &&
           g.getCell(cx, cy) > 0.7f;  // MRPT cell value = P(free)
}

}  // namespace

TEST(LabelsOffice, ObjectsSeenFromAFreeViewpointAreVisible) {
    if (!std::filesystem::exists(kOffice + "/global_variance.json"))
        GTEST_SKIP() << "the authors' data is absent (" << kOffice << "); this test needs it";
    const world::World w = world::importSimpMap(kOffice);
    std::vector<geometry::Box3D> boxes;
    for (const auto& o : w.objects.objects) boxes.push_back(o.box);
    camera::PinholeCamera cam;  // the authors' intrinsics
    int tried = 0, visible_masked = 0, visible_unmasked = 0;
    camera::ZBufferParams params;  // as simp-labels renders, at 1/8 resolution
    params.downscale = 8;
    params.wall_depth_margin_m = 0.0;
    params.max_distance_m = 30.0;
    params.walls_per_pixel = true;
    camera::ZBufferRenderer renderer;
    std::vector<camera::BoxView> views;
    const camera::FloorPlanGrid unmasked(w.floorplan);
    camera::FloorPlanGrid masked(w.floorplan);
    masked.clearWallsUnder(boxes, 0.10);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        // A viewpoint 1.2 m beyond the box's half diagonal, in the first of 8 directions whose
        // straight path to the object is free floor in the plan up to 0.15 m from the box.
        const Eigen::Vector2d c = boxes[i].center.head<2>();
        const double r = 0.5 * boxes[i].size.head<2>().norm() + 1.2;
        geometry::Box3D near_box = boxes[i];
        near_box.size += Eigen::Vector3d::Constant(0.3);
        for (int k = 0; k < 8; ++k) {
            const double a = k * M_PI / 4;
            const Eigen::Vector2d at = c + r * Eigen::Vector2d(std::cos(a), std::sin(a));
            bool ok = true;
            for (double s = 0; s <= r && ok; s += 0.025) {
                const Eigen::Vector2d p = at - s * Eigen::Vector2d(std::cos(a), std::sin(a));
                if (geometry::containsPoint(near_box, Eigen::Vector3d(p.x(), p.y(), boxes[i].center.z()))) break;
                ok = freeCell(w.floorplan, p.x(), p.y());
            }
            if (!ok) continue;
            const double yaw = a + M_PI;  // looking back at the object
            cam.world_T_camera = camera::toIsometry(mrpt::poses::CPose3D(mrpt::poses::CPose2D(at.x(), at.y(), 0)) +
                                                    obs::cameraPoseOnRobot(0, 0, 0.63, yaw));
            ++tried;
            renderer.render(cam, boxes, &masked, params, views);
            const double vm = views[i].visibleFraction();
            renderer.render(cam, boxes, &unmasked, params, views);
            const double vu = views[i].visibleFraction();
            visible_masked += vm > 0.5;
            visible_unmasked += vu > 0.5;
            break;
        }
    }
    ASSERT_GT(tried, 20) << "too few free viewpoints in the office map";
    // The viewpoint's centre line is free, so with the objects' own cells ignored most objects are
    // mostly visible (the rest: drawers under desks, objects in niches, hidden by boxes or walls off
    // the centre line; 77 of 87 with this data); without, the furniture outlines drawn in the plan
    // hide almost every object behind its own footprint (3 of 87).
    EXPECT_GT(visible_masked, 3 * tried / 4) << visible_masked << " of " << tried;
    EXPECT_LT(visible_unmasked, tried / 10) << visible_unmasked << " of " << tried;
}
