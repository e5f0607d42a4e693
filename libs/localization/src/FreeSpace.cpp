#include <simp/localization/FreeSpace.h>

#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <stdexcept>

namespace simp::localization {

FreeSpace::FreeSpace(const mrpt::maps::COccupancyGridMap2D& grid, double free_threshold)
    : m_x_min(grid.getXMin()),
      m_y_min(grid.getYMin()),
      m_res(grid.getResolution()),
      m_size_x(static_cast<int>(grid.getSizeX())),
      m_size_y(static_cast<int>(grid.getSizeY())),
      m_free(static_cast<std::size_t>(m_size_x) * m_size_y, 0) {
    for (int y = 0; y < m_size_y; ++y)
        for (int x = 0; x < m_size_x; ++x)
            if (grid.getCell(x, y) >= free_threshold) {
                const auto idx = static_cast<std::uint32_t>(y * m_size_x + x);
                m_free[idx] = 1;
                m_free_cells.push_back(idx);
            }
    if (m_free_cells.empty())
        throw std::invalid_argument("floor plan has no free cell (p_free >= " + std::to_string(free_threshold) + ")");
}

bool FreeSpace::isFree(double x_m, double y_m) const {
    const int x = static_cast<int>(std::floor((x_m - m_x_min) / m_res));
    const int y = static_cast<int>(std::floor((y_m - m_y_min) / m_res));
    if (x < 0 || y < 0 || x >= m_size_x || y >= m_size_y) return false;
    return m_free[static_cast<std::size_t>(y) * m_size_x + x] != 0;
}

mrpt::math::TPose2D FreeSpace::drawUniform() const {
    auto& rng = mrpt::random::getRandomGenerator();
    const std::size_t k = std::min<std::size_t>(
        m_free_cells.size() - 1, static_cast<std::size_t>(rng.drawUniform(0.0, static_cast<double>(m_free_cells.size()))));
    const std::uint32_t idx = m_free_cells[k];
    const int cx = static_cast<int>(idx % m_size_x), cy = static_cast<int>(idx / m_size_x);
    return {m_x_min + (cx + rng.drawUniform(0.0, 1.0)) * m_res, m_y_min + (cy + rng.drawUniform(0.0, 1.0)) * m_res,
            rng.drawUniform(-M_PI, M_PI)};
}

}  // namespace simp::localization
