#pragma once
// The staggered ("marker-and-cell", MAC) grid of the fluid solver.
//
// Harlow & Welch 1965 via Griebel et al. 1998 (jellyfish paper ref. [11]), ch. 3: velocity
// components live on the faces normal to them and pressure at cell centres, so that the
// discrete divergence of a cell and the pressure gradient across a face are central
// differences and the discrete projection has no checkerboard null space.
//
//        v(i,j+1)
//     +-----^-----+        cell (i, j) covers [i dx, (i+1) dx] × [j dx, (j+1) dx]
//     |           |        u(i, j) at (i dx,       (j + 1/2) dx)   i = 0..nx,   j = 0..ny-1
//  u(i,j)> p(i,j) >u(i+1,j)   v(i, j) at ((i + 1/2) dx, j dx)         i = 0..nx-1, j = 0..ny
//     |           |        p(i, j) at ((i + 1/2) dx, (j + 1/2) dx) i = 0..nx-1, j = 0..ny-1
//     +-----^-----+
//        v(i,j)
//
// Faces with i = 0 / nx (u) and j = 0 / ny (v) lie on the walls of the domain.

#include "fluid/array2.hpp"

namespace creaturelab::fluid {

/// Geometry and state of a uniform 2-D MAC grid with square cells.
struct MacGrid2 {
  MacGrid2() = default;
  MacGrid2(int cells_x, int cells_y, double cell_size_m)
      : nx(cells_x),
        ny(cells_y),
        dx_m(cell_size_m),
        u_m_per_s(cells_x + 1, cells_y),
        v_m_per_s(cells_x, cells_y + 1),
        pressure_pa(cells_x, cells_y) {}

  int nx = 0;         ///< cells along x
  int ny = 0;         ///< cells along y
  double dx_m = 0.0;  ///< side of a (square) cell, metres

  Array2 u_m_per_s;    ///< x-velocity on vertical faces, (nx + 1) × ny
  Array2 v_m_per_s;    ///< y-velocity on horizontal faces, nx × (ny + 1)
  Array2 pressure_pa;  ///< pressure at cell centres, nx × ny (gauge: mean zero in a closed box)

  double width_m() const { return nx * dx_m; }
  double height_m() const { return ny * dx_m; }
  long cellCount() const { return static_cast<long>(nx) * static_cast<long>(ny); }

  /// Positions (metres) of the samples, see the sketch above.
  Vec2 uPosition_m(int i, int j) const { return {i * dx_m, (j + 0.5) * dx_m}; }
  Vec2 vPosition_m(int i, int j) const { return {(i + 0.5) * dx_m, j * dx_m}; }
  Vec2 cellCentre_m(int i, int j) const { return {(i + 0.5) * dx_m, (j + 0.5) * dx_m}; }
};

/// A vector field stored like the velocity: x component on u faces, y component on v faces.
/// Used for the external force density (N/m^3) that the immersed boundary spreads onto the grid.
struct FaceVectorField2 {
  FaceVectorField2() = default;
  FaceVectorField2(int cells_x, int cells_y) : x(cells_x + 1, cells_y), y(cells_x, cells_y + 1) {}
  Array2 x;  ///< (nx + 1) × ny, on u faces
  Array2 y;  ///< nx × (ny + 1), on v faces
  void fill(double value) {
    x.fill(value);
    y.fill(value);
  }
};

}  // namespace creaturelab::fluid
