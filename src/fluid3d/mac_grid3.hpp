#pragma once
// The 3-D staggered (marker-and-cell) grid: Harlow & Welch 1965, the 2-D layout of
// fluid/mac_grid2.hpp with a third axis. Cell (i, j, k) covers [i, i+1] × [j, j+1] × [k, k+1] dx;
// pressure at its centre, velocity component a on the faces normal to axis a:
//   u(i, j, k) at (i, j+½, k+½) dx,  v at (i+½, j, k+½) dx,  w at (i+½, j+½, k) dx.
// Along a walled axis a component has n + 1 faces (0 and n on the walls); along a periodic axis
// n faces (face n is face 0).

#include <array>

#include "fluid3d/array3.hpp"
#include "fluid3d/fluid_params3.hpp"

namespace creaturelab::fluid3d {

/// Three face-centred components (velocity, or a force density), indexed by axis.
using FaceField3 = std::array<Array3, 3>;

struct MacGrid3 {
  MacGrid3() = default;
  MacGrid3(const std::array<int, 3>& cells, double cell_size_m, const Boundaries3& sides)
      : n(cells), dx_m(cell_size_m), boundaries(sides) {
    for (int a = 0; a < 3; ++a) {
      const std::array<int, 3> e = faceExtents(a);
      velocity_m_per_s[a] = Array3(e[0], e[1], e[2]);
    }
    pressure_pa = Array3(n[0], n[1], n[2]);
  }

  std::array<int, 3> n{0, 0, 0};  ///< cells along x, y, z
  double dx_m = 0.0;              ///< side of a cubic cell, metres
  Boundaries3 boundaries{};
  FaceField3 velocity_m_per_s;  ///< component a on the faces normal to axis a
  Array3 pressure_pa;           ///< at cell centres (mean zero in a closed box)

  bool periodic(int axis) const { return boundaries.axis[axis].periodic(); }
  /// Extents of component a's array.
  std::array<int, 3> faceExtents(int a) const {
    std::array<int, 3> e = n;
    if (!periodic(a)) e[a] += 1;
    return e;
  }
  /// Whether component a's faces at index m along axis a are known (a solid or inflow side's own faces).
  bool knownFace(int a, int m) const {
    if (periodic(a)) return false;
    const AxisBoundary3& b = boundaries.axis[a];
    return (m == 0 && b.low != BoundaryType3::open) || (m == n[a] && b.high != BoundaryType3::open);
  }
  /// The value of a known face (knownFace(a, m)): zero, or an inflow side's velocity.
  double knownFaceVelocity_m_per_s(int a, int m) const { return boundaries.axis[a].normalVelocity_m_per_s(m != 0); }
  long cellCount() const { return static_cast<long>(n[0]) * n[1] * n[2]; }
  double cellVolume_m3() const { return dx_m * dx_m * dx_m; }
  /// Position (metres) of component a's sample (i, j, k).
  std::array<double, 3> facePosition_m(int a, int i, int j, int k) const {
    std::array<double, 3> p{(i + 0.5) * dx_m, (j + 0.5) * dx_m, (k + 0.5) * dx_m};
    p[a] -= 0.5 * dx_m;
    return p;
  }
};

}  // namespace creaturelab::fluid3d
