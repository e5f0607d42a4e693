#include <simp/maps/SensorModelChecks.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace simp::maps {

void checkEta(double eta) {
    if (!(eta > 0.0 && eta < 1.0)) throw std::invalid_argument("eta = " + std::to_string(eta) + " must be in (0, 1)");
}

void checkProbabilityMapOptions(const ObjectProbabilityMap::Options& mp) {
    if (!(mp.resolution_m > 0.0)) throw std::invalid_argument("mp_resolution_m must be > 0");
    if (!(mp.min_probability > 0.0 && mp.min_probability < 1.0))
        throw std::invalid_argument("mp_min_probability must be in (0, 1)");
    if (!(mp.centre_noise_floor >= 0.0 && mp.centre_noise_floor <= 1.0))
        throw std::invalid_argument("mp_centre_noise_floor must be in [0, 1] (0 = the model as is)");
}

void checkNoiseReferenceRange(double noise_reference_range_m) {
    if (!(noise_reference_range_m >= 0.0 && std::isfinite(noise_reference_range_m)))
        throw std::invalid_argument("noise_reference_range_m must be >= 0 (0 = off)");
}

}  // namespace simp::maps
