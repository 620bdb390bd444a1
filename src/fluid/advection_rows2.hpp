#pragma once
// Row bookkeeping shared by the advection schemes (advection2.cpp, upwind_advection2.cpp):
// which faces of a component are unknowns, how the rows of both components are cut among
// threads (the solid walls' normal faces of a result: boundary2.hpp's set_solid_normal_faces).
#include <algorithm>

#include "fluid/array2.hpp"
#include "fluid/boundary2.hpp"
#include "fluid/staggered_sampler2.hpp"
#include "fluid/worker_pool.hpp"

namespace creaturelab::fluid {

// The faces a pass computes: unknown faces of one component, and their rows.
struct FaceBlock {
  int i_begin = 0, i_end = 0, j_begin = 0, j_end = 0;
};
template <FaceAxis kAxis>
FaceBlock faceBlock(const MacGrid2& grid, FaceRange unknown) {
  if constexpr (kAxis == FaceAxis::x) return {unknown.begin, unknown.end, 0, grid.ny};
  return {0, grid.nx, unknown.begin, unknown.end};
}

// The rows of the u block and those of the v block, each cut into the pool's pieces: piece p calls
// u_rows(rows, p) on its share of the u rows and v_rows(rows, p) on its share of the v rows. The
// cut is the one forPieces() makes of each block alone (viscosity, forces), so that a thread
// owning piece p finds those rows in its cache in the next stage (worker_pool.hpp).
template <class UBody, class VBody>
void forRowPieces(WorkerPool* workers, const FaceBlock& ub, const FaceBlock& vb, UBody&& u_rows, VBody&& v_rows) {
  const int parts = pieceCount(workers);
  auto piece_rows = [&](int part) {
    const auto [u0, u1] = WorkerPool::piece(ub.j_begin, ub.j_end, part, parts);
    const auto [v0, v1] = WorkerPool::piece(vb.j_begin, vb.j_end, part, parts);
    if (u0 < u1) u_rows(u0, u1, part);
    if (v0 < v1) v_rows(v0, v1, part);
  };
  if (parts == 1) {
    piece_rows(0);
    return;
  }
  workers->run(piece_rows);
}

// u.assign() and v.assign() of the grid's velocity, the copies shared among threads by
// forRowPieces (the rows each thread then reads first).
inline void assignVelocity(WorkerPool* workers, const MacGrid2& grid, const Walls& walls, StaggeredComponent2& u,
                            StaggeredComponent2& v) {
  u.prepare(FaceAxis::x, grid.nx, grid.ny);
  v.prepare(FaceAxis::y, grid.nx, grid.ny);
  const FaceBlock u_rows{0, grid.nx + 1, 0, grid.ny};
  const FaceBlock v_rows{0, grid.nx, 0, grid.ny + 1};
  forRowPieces(
      workers, u_rows, v_rows, [&](int j0, int j1, int) { u.copyRows(grid.u_m_per_s, j0, j1); },
      [&](int j0, int j1, int) { v.copyRows(grid.v_m_per_s, j0, j1); });
  u.fillGhosts(walls);
  v.fillGhosts(walls);
}

}  // namespace creaturelab::fluid
