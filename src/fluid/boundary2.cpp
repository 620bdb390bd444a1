#include "fluid/boundary2.hpp"

#include <algorithm>

namespace creaturelab::fluid {

void setSolidNormalFaces(const Walls& walls, Array2& u, Array2& v) {
  const int nx = v.nx();
  const int ny = u.ny();
  if (isSolid(walls.left)) {
    const double wall = solidWallNormalVelocity(walls.left, false);
    for (int j = 0; j < ny; ++j) u(0, j) = wall;
  }
  if (isSolid(walls.right)) {
    const double wall = solidWallNormalVelocity(walls.right, true);
    for (int j = 0; j < ny; ++j) u(nx, j) = wall;
  }
  if (isSolid(walls.bottom)) std::fill(v.row(0), v.row(0) + nx, solidWallNormalVelocity(walls.bottom, false));
  if (isSolid(walls.top)) std::fill(v.row(ny), v.row(ny) + nx, solidWallNormalVelocity(walls.top, true));
}

}  // namespace creaturelab::fluid
