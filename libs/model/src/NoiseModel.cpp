#include <simp/model/NoiseModel.h>

#include <cmath>

namespace simp::model {

bool NoiseModel::isValid() const {
    if (!mean_m.allFinite() || !cov_m2.allFinite() || !std::isfinite(exponent_b)) return false;
    if (exponent_b <= 0.0) return false;
    // Symmetric up to rounding of the numbers that were written out.
    const double scale = cov_m2.cwiseAbs().maxCoeff();
    if (std::abs(cov_m2(0, 1) - cov_m2(1, 0)) > 1e-12 * (1.0 + scale)) return false;
    // Positive definite (Sylvester): both leading minors > 0.
    return cov_m2(0, 0) > 0.0 && cov_m2(0, 0) * cov_m2(1, 1) - cov_m2(0, 1) * cov_m2(1, 0) > 0.0;
}

}  // namespace simp::model
