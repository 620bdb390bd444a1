#pragma once
// The matrix of the implicit viscosity step for one velocity component (diffusion2.hpp):
//   (1 + α d) x − α Σ_{unknown neighbours} x_n = x^n + α (Σ_{moving/inflow ghosts} 2 U_wall
//                                                     + Σ_{inflow wall faces} U_in),
// α = ν dt / dx², on the block of unknown faces. d counts neighbours: 1 for each face
// neighbour (unknown, or a solid wall's normal face, which is zero or an inflow wall's U_in), 0
// for a free-slip/open ghost (ghost = x) and 2 for a no-slip/moving/inflow ghost (ghost = 2U − x).
// Shared by the iterative and the fast direct solvers.

#include "fluid/array2.hpp"
#include "fluid/fluid_params.hpp"
#include "fluid/mac_grid2.hpp"
#include "fluid/staggered_sampler2.hpp"

namespace creaturelab::fluid {

/// The unknown block of one component and its per-face neighbour counts and wall terms.
struct DiffusionBlock2 {
  bool ready = false;
  FaceAxis axis = FaceAxis::x;
  Walls walls{};
  int i_begin = 0, i_end = 0, j_begin = 0, j_end = 0;  // the unknown block
  bool has_wall_rhs = false;
  Array2 count, wall_rhs;  // d and the wall terms, on the component's array (zero off the block)
  /// max over the block's rows of d + (unknown neighbours): by Gershgorin's theorem the
  /// matrix's spectrum lies in [1, 1 + α · max_row_sum] (d ≥ the unknown neighbours, so ≥ 1).
  double max_row_sum = 0.0;

  /// (Re)builds the block for a component array of nx × ny faces, unless it is already built
  /// for this shape and these walls. Returns true when it was rebuilt.
  bool prepare(FaceAxis face_axis, int nx, int ny, const Walls& new_walls);
};

/// y = A x on rows [jb, je) of the unknown block, and row_dots[j] = the x·y of row j. Entries
/// outside the block are never written. Neighbours outside the block are solid-wall normal
/// faces (zero in x; an inflow wall's value is in wall_rhs) or lie beyond the array (ghosts,
/// accounted for in `count`).
void applyDiffusionRows(const DiffusionBlock2& block, int jb, int je, double alpha, const Array2& x, Array2& y,
                          double* row_dots);

/// Ghost factor of a tangential component across `wall`: 0 (ghost = x) or 2 (ghost = 2U − x).
double diffusionGhostCount(const Wall& wall);

}  // namespace creaturelab::fluid
