#include "TestUtil.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

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
