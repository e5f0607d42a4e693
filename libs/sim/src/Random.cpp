#include <simp/sim/Random.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>

namespace simp::sim {

double Rng::uniform() {
    // 53 random mantissa bits -> [0, 1)
    return static_cast<double>(m_engine() >> 11) * (1.0 / 9007199254740992.0);
}

std::size_t Rng::index(std::size_t n) {
    if (n == 0) throw std::invalid_argument("Rng::index: empty range");
    return static_cast<std::size_t>(uniform() * static_cast<double>(n)) % n;
}

double Rng::normal(double mean, double std) {
    double u1 = uniform();
    while (u1 <= 0.0) u1 = uniform();
    const double u2 = uniform();
    return mean + std * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

double Rng::gamma(double shape) {
    if (!(shape > 0.0)) throw std::invalid_argument("Rng::gamma: shape must be > 0");
    if (shape < 1.0) {
        // Gamma(a) = Gamma(a + 1) * U^(1/a)
        double u = uniform();
        while (u <= 0.0) u = uniform();
        return gamma(shape + 1.0) * std::pow(u, 1.0 / shape);
    }
    const double d = shape - 1.0 / 3.0;
    const double c = 1.0 / std::sqrt(9.0 * d);
    for (;;) {
        double x = 0, v = 0;
        do {
            x = normal();
            v = 1.0 + c * x;
        } while (v <= 0.0);
        v = v * v * v;
        const double u = uniform();
        if (u < 1.0 - 0.0331 * x * x * x * x) return d * v;
        if (u > 0.0 && std::log(u) < 0.5 * x * x + d * (1.0 - v + std::log(v))) return d * v;
    }
}

int Rng::poisson(double lambda) {
    if (!(lambda >= 0.0) || lambda > 30.0) throw std::invalid_argument("Rng::poisson: lambda must be in [0, 30]");
    const double limit = std::exp(-lambda);
    int k = 0;
    double p = uniform();
    while (p > limit) {
        ++k;
        p *= uniform();
    }
    return k;
}

Eigen::Vector2d sampleCentreOffset(const model::NoiseModel& model, Rng& rng) {
    if (!model.isValid()) throw std::invalid_argument("sampleCentreOffset: invalid noise model");
    const double b = model.exponent_b;
    const double r = std::pow(2.0 * rng.gamma(2.0 / b), 1.0 / b);
    const double a = rng.uniform(0.0, 2.0 * M_PI);
    const Eigen::Matrix2d L = model.cov_m2.llt().matrixL();
    return model.mean_m + L * Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
}

}  // namespace simp::sim
