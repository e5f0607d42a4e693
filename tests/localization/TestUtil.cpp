#include "TestUtil.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <simp/obs/ObjectClasses.h>

#include <cmath>
#include <filesystem>

namespace simp::localization::test {

const Scenario& sharedScenario() {
    // One copy per test process: ctest runs tests in parallel processes, and a scenario rewritten by one
    // process while another reads its rawlog made the same-seed test see different inputs.
    static const Scenario sc = [] {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        const std::string owner =
            info ? std::string(info->test_suite_name()) + "." + info->name() : std::string("no_test");
        return makeScenario(std::string(SIMP_TEST_OUTPUT_DIR) + "/localization/scenario/" + owner, 42);
    }();
    return sc;
}

std::string freshOutputDir(const std::string& name) {
    const auto dir = std::filesystem::path(SIMP_TEST_OUTPUT_DIR) / "localization" / name;
    std::filesystem::remove_all(dir);
    return dir.string();
}

void runApp(LocalizeApp& app, const std::vector<std::string>& args) {
    std::vector<std::string> full{"simp-localize"};
    full.insert(full.end(), args.begin(), args.end());
    full.push_back("--quiet");
    app.initialize(full);
    app.run();
}

/// A camera observation of map objects `idx` of `w` seen from `robot` (exact boxes).
simp::obs::CObservationObjects3D::Ptr observe(const simp::world::World& w, const mrpt::math::TPose2D& robot,
                                              const std::vector<int>& idx) {
    auto o = simp::obs::CObservationObjects3D::Create();
    const auto cam = simp::obs::cameraPoseOnRobot(0.1, 0, 0.5, 0.0);
    o->setCameraPose(cam);
    o->setClassNames(simp::obs::defaultClassNames());
    const mrpt::poses::CPose3D world_T_cam = mrpt::poses::CPose3D(mrpt::poses::CPose2D(robot)) + cam;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.matrix() = world_T_cam.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
    for (int i : idx) {
        simp::obs::Detection3D d;
        d.class_id = static_cast<std::uint16_t>(w.objects.objects[static_cast<std::size_t>(i)].class_id);
        d.confidence = 0.95f;
        d.box_in_camera = w.objects.objects[static_cast<std::size_t>(i)].box.transformed(T.inverse());
        o->addDetection(d);
    }
    return o;
}

std::shared_ptr<simp::maps::CObjectMap> makeMap(const simp::world::World& w) {
    auto map = std::make_shared<simp::maps::CObjectMap>();
    map->setData(w.objects);
    return map;
}

double translationError(const mrpt::math::TPose2D& est, const mrpt::math::TPose2D& gt) {
    return std::hypot(est.x - gt.x, est.y - gt.y);
}

double headingError(const mrpt::math::TPose2D& est, const mrpt::math::TPose2D& gt) {
    return std::abs(mrpt::math::wrapToPi(est.phi - gt.phi));
}

}  // namespace simp::localization::test
