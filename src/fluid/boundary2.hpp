#pragma once
// Wall boundary conditions on the MAC grid, by ghost values (Griebel et al. 1998, ch. 3).
//
// Normal velocity: a solid wall (free-slip, no-slip, moving) holds u·n = 0 on its faces, an
// inflow wall its prescribed speed into the domain; an open wall's faces are unknowns like
// interior faces. An inflow wall is solid everywhere else (known faces, Neumann pressure), so the
// projection keeps its flux: the flux a held band of faces next to an open wall lost to the
// projection (the flyer's floor source) cannot leak away here.
// Tangential velocity: the tangential component's samples sit half a cell from the wall, so a
// ghost sample half a cell outside, mirrored across the wall, sets the wall value:
//   free-slip and open  ghost = interior            (∂u_t/∂n = 0)
//   no-slip             ghost = −interior           (u_t = 0 on the wall)
//   moving and inflow   ghost = 2 U_wall − interior  (u_t = U_wall on the wall)
// Pressure: solid walls are Neumann (∂p/∂n = 0, no flux); an open wall is Dirichlet p = 0 on
// the wall itself, i.e. ghost pressure = −interior pressure.

#include "fluid/fluid_params.hpp"
#include "fluid/mac_grid2.hpp"

namespace creaturelab::fluid {

inline bool isSolid(const Wall& wall) { return wall.type != WallType::open; }

/// Ghost value of a tangential velocity component half a cell outside `wall`.
inline double tangentialGhost(const Wall& wall, double interior) {
  switch (wall.type) {
    case WallType::free_slip:
    case WallType::open:
      return interior;
    case WallType::no_slip:
      return -interior;
    case WallType::moving:
    case WallType::inflow:
      return 2.0 * wall.tangential_velocity_m_per_s - interior;
  }
  return interior;
}

/// The velocity component normal to a solid wall on its faces, along +x (left and right walls) or
/// +y (bottom and top): zero, or an inflow wall's speed pointed into the domain. `high_wall` is
/// true for the right and top walls.
inline double solidWallNormalVelocity(const Wall& wall, bool high_wall) {
  if (wall.type != WallType::inflow) return 0.0;
  return high_wall ? -wall.inflow_m_per_s : wall.inflow_m_per_s;
}

/// Range [begin, end) of the face indices normal to a pair of walls that are unknowns:
/// for u faces the i range (walls left/right), for v faces the j range (walls bottom/top).
struct FaceRange {
  int begin = 0;
  int end = 0;
};
inline FaceRange unknownFaces(const Wall& low_wall, const Wall& high_wall, int cells) {
  return {isSolid(low_wall) ? 1 : 0, isSolid(high_wall) ? cells : cells + 1};
}
inline FaceRange unknownUColumns(const MacGrid2& grid, const Walls& walls) {
  return unknownFaces(walls.left, walls.right, grid.nx);
}
inline FaceRange unknownVRows(const MacGrid2& grid, const Walls& walls) {
  return unknownFaces(walls.bottom, walls.top, grid.ny);
}

/// Sets the normal velocity on solid walls' faces of u ((nx + 1) × ny) and v (nx × (ny + 1)):
/// zero (u·n = 0), or an inflow wall's speed.
void setSolidNormalFaces(const Walls& walls, Array2& u, Array2& v);

/// The same on the grid's velocity.
inline void enforceWallNormalVelocity(MacGrid2& grid, const Walls& walls) {
  setSolidNormalFaces(walls, grid.u_m_per_s, grid.v_m_per_s);
}

}  // namespace creaturelab::fluid
