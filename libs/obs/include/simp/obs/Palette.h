#pragma once
/// \file Palette.h
/// The one palette of the project: every colour a picture uses, 2D figures (simp::eval, BGR via
/// simp::eval::toBgr) and 3D views (RawLogViewer, .3Dscene files, OctoMap export) alike.
///  - a class has one colour everywhere, chosen by its **name** (not by its id, which depends on
///    the class list of the world or detector at hand): the 14 classes of the paper's detector
///    (defaultClassNames()) have fixed colours, any other name a deterministic one;
///  - what figures show besides classes (ground truth, estimate, matches, changes, ...) has a
///    named colour in `figure_colors`;
///  - series of the batch figures (rows, sequences) take seriesColorRgb.
/// doc/figures.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace simp::obs {

/// An RGB colour, 0..255 per channel.
using Rgb = std::array<std::uint8_t, 3>;

/// `name` lower-cased, '_' and '-' read as ' ', surrounding blanks dropped: "Potted_Plant" and
/// "potted plant" are the same class (the detector's files spell it either way).
std::string canonicalClassName(const std::string& name);

/// Colour of the class called `class_name` (canonicalClassName): the detector's 14 classes in
/// defaultClassNames() order get Tableau 10 then four light Tableau 20 colours; any other name one
/// of kFallbackClassColors chosen by the FNV-1a hash of its canonical name (the same on every run
/// and machine; two unknown classes may share a colour, the legend names them).
Rgb classColorRgb(const std::string& class_name);

/// Colour of class `class_id` of the list `class_names` (a world's or an observation's):
/// classColorRgb(class_names[class_id]); an id outside the list is named "class <id>".
Rgb classColorRgb(int class_id, const std::vector<std::string>& class_names);

/// Colour of class `class_id` of the detector's list (defaultClassNames()), for callers that
/// hold no class list.
Rgb classColorRgb(int class_id);

/// The colours unknown class names hash into: the six light Tableau 20 colours no detector class uses.
inline constexpr std::array<Rgb, 6> kFallbackClassColors = {
    {{174, 199, 232}, {196, 156, 148}, {247, 182, 210}, {199, 199, 199}, {219, 219, 141}, {158, 218, 229}}};

/// Colour of series `i` of a chart (a batch figure's rows or sequences): Tableau 10, repeating.
Rgb seriesColorRgb(std::size_t i);

/// What the figures show besides object classes. The colours drawn over class colours (paths,
/// particles, kidnap marks: drawTrajectoryMap, overview.png) are none of the class colours, so a
/// legend never shows one colour twice; figures without classes (map evaluation, change report)
/// use red and green by their usual meaning.
namespace figure_colors {
inline constexpr Rgb kGroundTruth{0, 110, 0};            ///< ground-truth path (dark green); matched and added objects
inline constexpr Rgb kEstimate{200, 0, 200};             ///< estimated path (magenta), after convergence
inline constexpr Rgb kEstimateBefore{255, 165, 0};       ///< estimate before convergence (no classes in that figure)
inline constexpr Rgb kConvergence{0, 90, 200};           ///< convergence marker and instant
inline constexpr Rgb kDivergence{255, 0, 0};             ///< divergence instant
inline constexpr Rgb kParticles{0, 0, 150};              ///< the filter's particles (navy)
inline constexpr Rgb kKidnapLifted{0, 0, 0};             ///< ring where a kidnapped robot was lifted
inline constexpr Rgb kKidnapPutDown{255, 215, 0};        ///< dot where it was put down (gold)
inline constexpr Rgb kWrong{220, 30, 30};                ///< false map objects, removed objects
inline constexpr Rgb kMoved{255, 140, 0};                ///< moved objects
inline constexpr Rgb kMissed{0, 120, 220};               ///< ground-truth objects the map missed
inline constexpr Rgb kUnchanged{150, 150, 150};          ///< objects a change report leaves alone
inline constexpr Rgb kUnseen{120, 70, 170};              ///< objects a map update could not check (never in view)
inline constexpr Rgb kDoorClosed{0, 160, 160};           ///< doors a map update found closed (teal)
inline constexpr Rgb kText{0, 0, 0};                     ///< text, axes, the scale bar
inline constexpr Rgb kGrid{215, 215, 215};               ///< grid lines of charts
inline constexpr Rgb kSigma1{255, 0, 0};                 ///< 1-sigma ellipse of a noise plot
inline constexpr Rgb kSigma2{255, 165, 0};               ///< 2-sigma ellipse
inline constexpr Rgb kSigma3{255, 255, 255};             ///< 3-sigma ellipse, marker and title over the heat map
}  // namespace figure_colors

}  // namespace simp::obs
