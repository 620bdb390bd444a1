#pragma once
// The discrete projection on the 3-D MAC grid (Chorin's projection, Stam 1999 §2.2; Eqs. 7–8 of
// Lentine et al. 2010 §4.1 with p̂ = p dt).
//
// With q = p dt/ρ (m²/s), a face between cells c and c+1 along axis a is updated as
// u_f = u*_f − (q_{c+1} − q_c)/dx. Zero flux sum in every cell gives A q = b with
//   (A q)_c = Σ_{6 neighbours} (q_c − q_nb),   b_c = −dx · Σ_a (u*_a(c + ½) − u*_a(c − ½)),
// neighbours beyond a solid wall or an inflow side being ghosts equal to q_c (no change of the
// known flux, which b carries) and beyond an open side
// ghosts −q_c (p = 0 on the side): the pressure stencil of stencil3.hpp with diag 6, off −1.
// After the update, (A q − b)_c = dx · (flux sum of c): the residual is the divergence left.

#include <vector>

#include "fluid3d/mac_grid3.hpp"
#include "fluid3d/parallel3.hpp"

namespace creaturelab::fluid3d {

/// b = −dx · (flux sum) per cell (m²/s).
void projectionRhs(const MacGrid3& grid, Array3& b, WorkerPool* pool);
/// u ← u − factor · (φ_{c+1} − φ_c) on every unknown face (interior, periodic and open-side faces):
/// factor = 1/dx for φ = q.
void subtractGradient(MacGrid3& grid, const Array3& phi, double factor_per_m, WorkerPool* pool);
/// max over cells of |∇·u| (1/s).
double maxDivergence_per_s(const MacGrid3& grid, WorkerPool* pool);
/// The known normal faces: zero on the solid walls, the prescribed speed into the box on inflow sides.
void enforceSolidWalls(MacGrid3& grid);

}  // namespace creaturelab::fluid3d
