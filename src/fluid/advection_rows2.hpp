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
FaceBlock face_block(const MacGrid2& grid, FaceRange unknown) {
  if constexpr (kAxis == FaceAxis::x) return {unknown.begin, unknown.end, 0, grid.ny};
  return {0, grid.nx, unknown.begin, unknown.end};
}

// Rows of the u block and then of the v block as one index range, cut into one piece per
// thread: u_rows(rows, part) is called for the u rows and v_rows for the v rows of each piece.
template <class UBody, class VBody>
void for_row_pieces(WorkerPool* workers, const FaceBlock& ub, const FaceBlock& vb, UBody&& u_rows, VBody&& v_rows) {
  const int nu = ub.j_end - ub.j_begin;
  const int nv = vb.j_end - vb.j_begin;
  for_pieces(workers, 0, nu + nv, [&](int lo, int hi, int part) {
    if (lo < nu) u_rows(ub.j_begin + lo, ub.j_begin + std::min(hi, nu), part);
    if (hi > nu) v_rows(vb.j_begin + std::max(lo, nu) - nu, vb.j_begin + hi - nu, part);
  });
}

}  // namespace creaturelab::fluid
