#pragma once
// Immersed-boundary transfer between Lagrangian markers and the 3-D MAC grid (fluid3d/mac_grid3.hpp):
// the 2-D transfer of ib/transfer.hpp with a third axis (Peskin 2002, Acta Numerica 11, §6):
//
//   spread:       f(x_face) += Σ_k F_k δ_h(x_face − X_k)                 (force density, N/m³)
//   interpolate:  U_k        = Σ_faces u(x_face) δ_h(x_face − X_k) dx³    (m/s)
//
// with δ_h(x, y, z) = φ(x/dx) φ(y/dx) φ(z/dx) / dx³, φ one of ib's 1-D kernels (ib/kernel.hpp).
// Component a of a force or velocity lives on the faces normal to axis a. The same weights serve
// both operations, so <S F, u>_grid = dx³ Σ_faces f u = Σ_k F_k · U_k = <F, I u>_markers (S = Iᵀ/dx³),
// and since each 1-D weight set has φ's partition of unity and zero first moment, the spread force
// density carries exactly the markers' total force, dx³ Σ_faces f = Σ_k F_k, and their torque,
// dx³ Σ_faces x_face × f = Σ_k X_k × F_k (each face position's coordinate along an axis averages,
// under a marker's weights, to the marker's); interpolation of a linear field is exact.
//
// Periodic axes wrap the stencil around. Along a walled axis every stencil face must be one the
// solver updates: for the component normal to that axis faces 1..n−1 (0 and n lie on the walls),
// for the others cells 0..n−1. So a marker keeps support/2 cells (2 for peskin4) from a wall;
// locate() throws otherwise. Markers are visited in index order: the sums are the same on every
// run and for any thread count of the fluid (the transfer itself is serial). No I/O.

#include <array>
#include <span>
#include <vector>

#include "fluid3d/mac_grid3.hpp"
#include "ib/kernel.hpp"

namespace creaturelab::coupling3d {

using Vec3 = std::array<double, 3>;

/// The faces of one component that one marker touches: face (i0 + a, j0 + b, k0 + c), wrapped on a
/// periodic axis, has weight w[0][a] w[1][b] w[2][c], a, b, c = 0..support−1.
struct FaceStencil3 {
  std::array<int, 3> start{};
  double w[3][ib::kMaxKernelSupportCells] = {};
};

class Transfer3 {
 public:
  /// Stencils of every marker on the grid's three face families. Throws std::invalid_argument
  /// naming the marker and its position if one is not finite or its stencil would reach a wall's
  /// face or beyond, or if the grid has no cells. After a throw the transfer holds no markers.
  void locate(const fluid3d::MacGrid3& grid, ib::Kernel kernel, std::span<const Vec3> positions_m);

  /// ADDS Σ_k F_k δ_h(x_face − X_k) (N/m³) into force_density; forces in N. Throws
  /// std::invalid_argument if the sizes differ from the located markers and grid.
  void spread(std::span<const Vec3> forces_n, fluid3d::FaceField3& force_density_n_per_m3) const;
  /// U_k = Σ_faces u w (the weights sum to 1); overwrites velocities. Throws like spread.
  void interpolate(const fluid3d::FaceField3& velocity_m_per_s, std::span<Vec3> velocities_m_per_s) const;

  int markerCount() const { return static_cast<int>(stencils_.size()); }
  ib::Kernel kernel() const { return kernel_; }
  int support() const { return support_; }
  /// Stencil of marker k for component a.
  const FaceStencil3& stencil(int marker, int a) const { return stencils_.at(static_cast<std::size_t>(marker))[a]; }

 private:
  ib::Kernel kernel_ = ib::Kernel::peskin4;
  int support_ = 4;
  std::array<int, 3> n_{};
  std::array<bool, 3> periodic_{};
  std::array<std::array<int, 3>, 3> extents_{};  // extents_[a]: face extents of component a
  double inv_cell_volume_per_m3_ = 0.0;
  std::vector<std::array<FaceStencil3, 3>> stencils_;
};

}  // namespace creaturelab::coupling3d
