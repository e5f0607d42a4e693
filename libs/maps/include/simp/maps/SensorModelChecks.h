#pragma once
/// \file SensorModelChecks.h
/// Checks of the parameters several 3D-object sensor models share; each throws
/// std::invalid_argument naming the parameter (the .ini key).

#include <simp/maps/ObjectProbabilityMap.h>

namespace simp::maps {

/// eta of Eq. combined (every model's floor) must be in (0, 1).
void checkEta(double eta);
/// The m_p raster options (SimpSensorModel, CentreSensorModel): resolution > 0, support
/// probability in (0, 1).
void checkProbabilityMapOptions(const ObjectProbabilityMap::Options& mp);
/// The range growth of the detection noise: >= 0 and finite (0 = off).
void checkNoiseReferenceRange(double noise_reference_range_m);

}  // namespace simp::maps
