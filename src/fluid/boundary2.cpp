#include "fluid/boundary2.hpp"

#include <algorithm>

namespace creaturelab::fluid {

void set_solid_normal_faces(const Walls& walls, Array2& u, Array2& v) {
  const int nx = v.nx();
  const int ny = u.ny();
  if (is_solid(walls.left)) {
    const double wall = solid_wall_normal_velocity(walls.left, false);
    for (int j = 0; j < ny; ++j) u(0, j) = wall;
  }
  if (is_solid(walls.right)) {
    const double wall = solid_wall_normal_velocity(walls.right, true);
    for (int j = 0; j < ny; ++j) u(nx, j) = wall;
  }
  if (is_solid(walls.bottom)) std::fill(v.row(0), v.row(0) + nx, solid_wall_normal_velocity(walls.bottom, false));
  if (is_solid(walls.top)) std::fill(v.row(ny), v.row(ny) + nx, solid_wall_normal_velocity(walls.top, true));
}

}  // namespace creaturelab::fluid
