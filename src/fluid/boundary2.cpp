#include "fluid/boundary2.hpp"

namespace creaturelab::fluid {

void enforce_wall_normal_velocity(MacGrid2& grid, const Walls& walls) {
  if (is_solid(walls.left)) {
    for (int j = 0; j < grid.ny; ++j) grid.u_m_per_s(0, j) = 0.0;
  }
  if (is_solid(walls.right)) {
    for (int j = 0; j < grid.ny; ++j) grid.u_m_per_s(grid.nx, j) = 0.0;
  }
  if (is_solid(walls.bottom)) {
    for (int i = 0; i < grid.nx; ++i) grid.v_m_per_s(i, 0) = 0.0;
  }
  if (is_solid(walls.top)) {
    for (int i = 0; i < grid.nx; ++i) grid.v_m_per_s(i, grid.ny) = 0.0;
  }
}

}  // namespace creaturelab::fluid
