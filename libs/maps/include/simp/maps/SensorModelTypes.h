#pragma once
/// \file SensorModelTypes.h
/// Which 3D-object sensor model to use and the likelihood parameters of all of them, as the .ini's
/// [<prefix>_likelihoodOpts] gives them (CObjectMap::TLikelihoodOptions::modelParams()); SensorModel
/// builds the selected model with its own parameter struct (SimpSensorModelParams, ...). The models and
/// their names are declared once with the localization methods (simp/model/LocalizationMethods.h).

#include <simp/maps/ObjectProbabilityMap.h>
#include <simp/model/LocalizationMethods.h>

namespace simp::maps {

/// The paper's model and its three baselines; part of CObjectMap's interface, hence named here too.
using model::SensorModelType;

/// Which model, and the parameters of every model (each takes its own: simpParams(), ... in SensorModel.h).
struct SensorModelParams {
    SensorModelType type = SensorModelType::Simp;
    double eta = 0.1;                   ///< Eq. combined: likelihood of a false association, in (0, 1) (all)
    ObjectProbabilityMap::Options mp;   ///< m_p raster (simp, d)
    double edt_sigma_m = 0.3;           ///< EDT: std. dev. of the centre distance (m)
    double edt_max_distance_m = 2.0;    ///< EDT: distances are clamped to this (m)
    double edt_resolution_m = 0.05;     ///< EDT raster cell (m)
    /// Range growth of the detection noise: a detection whose centre is r > this (m) from the robot
    /// is scored with the noise model widened by s = r / this (Sigma -> s^2 Sigma; EDT: sigma -> s
    /// sigma). Monocular depth error grows with distance. 0 = off (the paper's model). simp, d, edt.
    double noise_reference_range_m = 0.0;
    /// > 0: std (rad) of a detected box's yaw about its map object's, on the 4-fold circle (simp
    /// only; SimpSensorModelParams::yaw_sigma_rad). 0 = off (the paper).
    double yaw_sigma_rad = 0.0;

    bool operator==(const SensorModelParams& o) const {
        return type == o.type && eta == o.eta && mp.resolution_m == o.mp.resolution_m &&
               mp.min_probability == o.mp.min_probability &&
               mp.skip_classes_without_noise == o.mp.skip_classes_without_noise &&
               mp.unmodelled_noise_std_m == o.mp.unmodelled_noise_std_m &&
               mp.centre_noise_floor == o.mp.centre_noise_floor && edt_sigma_m == o.edt_sigma_m &&
               edt_max_distance_m == o.edt_max_distance_m && edt_resolution_m == o.edt_resolution_m &&
               noise_reference_range_m == o.noise_reference_range_m && yaw_sigma_rad == o.yaw_sigma_rad;
    }
    bool operator!=(const SensorModelParams& o) const { return !(*this == o); }
};

}  // namespace simp::maps
