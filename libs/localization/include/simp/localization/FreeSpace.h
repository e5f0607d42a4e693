#pragma once
/// \file FreeSpace.h
/// The free cells of the floor plan: where a robot can be (particle initialization and pruning).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <vector>

namespace simp::localization {

class FreeSpace {
   public:
    FreeSpace() = default;
    /// Cells with p_free >= free_threshold are free. \throw std::invalid_argument when none is.
    FreeSpace(const mrpt::maps::COccupancyGridMap2D& grid, double free_threshold);

    /// True when the world point (x, y) (m) falls in a free cell.
    bool isFree(double x_m, double y_m) const;
    /// A pose drawn uniformly over the free cells (uniform inside the cell) with a uniform
    /// heading in [-pi, pi), using mrpt::random::getRandomGenerator().
    mrpt::math::TPose2D drawUniform() const;

   private:
    double m_x_min = 0, m_y_min = 0, m_res = 1;
    int m_size_x = 0, m_size_y = 0;
    std::vector<std::uint8_t> m_free;           ///< row-major, y index major
    std::vector<std::uint32_t> m_free_cells;    ///< indices into m_free
};

}  // namespace simp::localization
