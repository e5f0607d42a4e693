#pragma once
/// \file TestUtil.h
/// Shared by the localization tests: the generated scenario (built once per process) and
/// helpers to run simp-localize in-process.

#include "SyntheticScenario.h"

#include <simp/localization/LocalizeApp.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/CObservationObjects3D.h>
#include <simp/world/World.h>

#include <memory>
#include <string>
#include <vector>

namespace simp::localization::test {

/// The scenario under SIMP_TEST_OUTPUT_DIR/localization/scenario (generated on first use).
const Scenario& sharedScenario();

/// Output directory for a test (created empty).
std::string freshOutputDir(const std::string& name);

/// Runs `app` with these arguments (program name prepended, --quiet appended).
void runApp(LocalizeApp& app, const std::vector<std::string>& args);

/// An object map holding the objects of `w` (default options).
std::shared_ptr<simp::maps::CObjectMap> makeMap(const simp::world::World& w);
/// A camera observation of map objects `idx` of `w` seen from `robot` (exact boxes, confidence 0.95).
simp::obs::CObservationObjects3D::Ptr observe(const simp::world::World& w, const mrpt::math::TPose2D& robot,
                                              const std::vector<int>& idx);
/// Pose error of `est` w.r.t. `gt`: translation (m) and absolute heading difference (rad).
double translationError(const mrpt::math::TPose2D& est, const mrpt::math::TPose2D& gt);
double headingError(const mrpt::math::TPose2D& est, const mrpt::math::TPose2D& gt);

}  // namespace simp::localization::test
