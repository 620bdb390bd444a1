#include "fluid/boundary2.hpp"

#include <algorithm>

namespace creaturelab::fluid {

void enforce_wall_normal_velocity(MacGrid2& grid, const Walls& walls) {
  if (is_solid(walls.left)) {
    const double u = solid_wall_normal_velocity(walls.left, false);
    for (int j = 0; j < grid.ny; ++j) grid.u_m_per_s(0, j) = u;
  }
  if (is_solid(walls.right)) {
    const double u = solid_wall_normal_velocity(walls.right, true);
    for (int j = 0; j < grid.ny; ++j) grid.u_m_per_s(grid.nx, j) = u;
  }
  if (is_solid(walls.bottom)) {
    std::fill(grid.v_m_per_s.row(0), grid.v_m_per_s.row(0) + grid.nx, solid_wall_normal_velocity(walls.bottom, false));
  }
  if (is_solid(walls.top)) {
    std::fill(grid.v_m_per_s.row(grid.ny), grid.v_m_per_s.row(grid.ny) + grid.nx,
              solid_wall_normal_velocity(walls.top, true));
  }
}

}  // namespace creaturelab::fluid
