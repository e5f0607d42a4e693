#pragma once
/// \file Angle.h
/// Angle wrapping with the exact bits of MRPT's mrpt::math::wrapToPi / wrapTo2Pi, without their
/// fmod for the angles that are already within one turn (the filter wraps every particle's
/// heading at every step: fmod was a few per cent of a run).

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace simp::localization {

/// mrpt::math::wrapTo2Pi(a), bit for bit: fmod(x, 2 pi) is x itself when |x| < 2 pi.
inline double wrapTo2Pi(double a) {
    constexpr double kTwoPi = 2.0 * M_PI;
    if (a >= 0.0 && a < kTwoPi) return a;        // was_neg false, fmod exact
    if (a < 0.0 && a > -kTwoPi) return a + kTwoPi;  // was_neg true, fmod exact
    return mrpt::math::wrapTo2Pi(a);
}

/// mrpt::math::wrapToPi(a) = wrapTo2Pi(a + pi) - pi, bit for bit (so not the identity on
/// (-pi, pi]: (a + pi) - pi rounds).
inline double wrapToPi(double a) { return wrapTo2Pi(a + M_PI) - M_PI; }

}  // namespace simp::localization
