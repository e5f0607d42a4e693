#pragma once
/// \file Office.h
/// The built-in office world: a procedural floor (OfficeLayout), furnished room by room with
/// the paper's classes, with per-class detection noise models.

#include <simp/sim/OfficeLayout.h>
#include <simp/world/World.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace simp::sim {

/// Per-class centre-noise models (m) for `class_names`, with the magnitudes of the authors'
/// `class_noise.csv` fitted on real Cube R-CNN detections (pixels of 0.05 m; mean = (mx, my),
/// Sigma = diag(sx^2, sy^2), exponent b). Classes the authors did not model (door, box, chair,
/// person) and unknown names get nullopt.
std::vector<std::optional<model::NoiseModel>> officeClassNoise(const std::vector<std::string>& class_names);

/// A generated office: the world and the layout it came from (room types, door gaps).
struct GeneratedOffice {
    world::World world;
    OfficeLayout layout;
};

/// Generates the office floor for `seed` (same seed and params -> same world).
GeneratedOffice generateOfficeWithLayout(const OfficeParams& params, std::uint64_t seed);
/// Same, the world only.
world::World generateOffice(const OfficeParams& params, std::uint64_t seed);

/// Furnishes one room by its type (desks, tables, chairs, cabinets, ... by the room's purpose),
/// keeping its door wall free of wall-mounted boards. Appends to ctx.objects.
void furnishRoom(struct PlacementContext& ctx, const Room& room, Rng& rng);

}  // namespace simp::sim
