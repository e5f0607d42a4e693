#pragma once
/// \file SessionTurn.h
/// Whether an object of an earlier map was turned: the heading of this session's boxes of it
/// against its earlier box (map update, MapUpdate.h "moved"). Furniture that is moved is usually
/// turned too; a short move whose detections still associate with the old object leaves its
/// centre within the class noise of where it was (no displacement test separates it from objects
/// that are there, doc/mapping.md), but its heading, averaged over many windows, does.

#include <simp/geometry/Box3D.h>

#include <vector>

namespace simp::mapping {

/// One integration window's box of an earlier object (the merged local object, in the window
/// it was matched) and its weight (its detections).
struct SessionBox {
    geometry::Box3D box;
    double weight = 1;
};

struct TurnEstimate {
    double turn_rad = 0;       ///< mean heading change, in (-pi/4, pi/4] (an upright box repeats every 90 deg)
    double std_error_rad = 0;  ///< standard error of that circular mean (Fisher's, from the windows' spread)
    double concentration = 0;  ///< mean resultant length of the headings on the 4-fold circle, in [0, 1]
    int windows = 0;           ///< windows that gave a heading
};

/// Headings less concentrated than this on the 4-fold circle (a spread of about 17 deg: a round
/// object whose heading the detector guesses) tell no turn, whatever their mean.
constexpr double kMinTurnConcentration = 0.5;

/// The turn of `before` seen in `windows`: each box is taken in its representation closest to
/// `before` (closestEquivalent: a box turned by 90 deg with its sides swapped is the same solid),
/// and the weighted circular mean of the heading differences is taken on the 4-fold circle.
TurnEstimate estimateTurn(const geometry::Box3D& before, const std::vector<SessionBox>& windows);

/// Turned: at least `min_windows` windows, concentration >= kMinTurnConcentration, |turn| >=
/// min_turn_rad and >= sigmas standard errors.
bool isTurned(const TurnEstimate& t, int min_windows, double min_turn_rad, double sigmas);

}  // namespace simp::mapping
