#pragma once
// Immersed-boundary transfer between Lagrangian markers and the fluid's MAC grid
// (Peskin 2002, "The immersed boundary method", Acta Numerica 11; Rudolf & Mould 2009
// §3.2):
//
//   spread:       f(x_face) += Σ_k F_k delta_h(x_face − X_k)          (force density, N/m³)
//   interpolate:  U_k        = Σ_faces u(x_face) delta_h(x_face − X_k) dx²   (m/s)
//
// with delta_h(x, y) = phi(x / dx) phi(y / dx) / dx² (kernel.hpp). Each velocity component
// is handled on its own faces: the x components (forces F_x, velocities u) on u faces at
// (i dx, (j + 1/2) dx), the y components on v faces at ((i + 1/2) dx, j dx)
// (fluid/mac_grid2.hpp). The same weights serve both operations, so with the discrete inner
// products <f, u>_grid = dx² Σ_faces f u and <F, U>_markers = Σ_k F_k · U_k,
//
//     <S F, u>_grid = <F, I u>_markers,      i.e. S = I^T / dx²,
//
// the adjointness behind the energy balance of the coupled method (Peskin 2002: the power the
// markers put into the fluid equals the power the fluid does on the markers), and since
// the weights of a marker sum to 1 the total force is conserved: dx² Σ_faces S F = Σ_k F_k.
//
// Markers must keep the whole stencil on faces inside the fluid: faces on a wall (u at i = 0, nx;
// v at j = 0, ny) carry the wall's no-penetration condition and receive no weight. So a marker
// must lie at least support/2 cells (1 for bilinear, 2 for peskin4) from every wall; locate()
// throws otherwise. (At exactly support/2 cells from the right or top wall the stencil, which
// starts at the face floor(x/dx) − support/2 + 1, would end on the wall with weight 0; that
// position is refused too, so the allowed region is [s/2 dx, (n − s/2) dx) on each axis, up to
// the rounding of x / dx at its edges.)

#include <span>

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "fluid/array2.hpp"
#include "fluid/mac_grid2.hpp"
#include "ib/kernel.hpp"

namespace creaturelab::ib {

/// The faces one marker touches on one face family (u or v) and their weights: face
/// (i0 + a, j0 + b) has weight wx[a] · wy[b] for a, b = 0..support−1. Entries past the
/// support are 0.
struct FaceStencil {
  int i0 = 0;  ///< first face index along x
  int j0 = 0;  ///< first face index along y
  double wx[kMaxStencilFaces] = {};
  double wy[kMaxStencilFaces] = {};
};

/// Weights of every marker on u faces and v faces of one MacGrid2 (fluid/mac_grid2.hpp),
/// computed once per step by locate() and reused by spread() and interpolate(), which are
/// therefore exact adjoints of each other.
///
/// Deterministic: markers are visited in index order and each stencil row by row, so the
/// sums are the same on every run. No allocation after the first locate() with the largest
/// marker count, except in gram(), which builds its neighbour index and the entries on and below
/// the diagonal at each call; no I/O.
class Transfer {
 public:
  /// Throws std::invalid_argument naming the marker index and position if a marker's stencil
  /// would reach outside the grid's interior faces (a marker too close to a wall) or is not
  /// finite, or if the grid has no cells or a cell size that is not a positive number.
  /// After a throw the transfer holds no markers.
  ///
  /// `kernel_scale` m stretches the kernel to m cells per kernel unit (stretched_kernel_weights_1d):
  /// a delta function of width m · support · dx; 1 is Peskin's grid-scaled delta_h. Throws
  /// std::invalid_argument for a scale stencilFaces() refuses.
  ///
  /// `marker_scales`, if not empty, gives each marker its own stretch (one per marker, each accepted
  /// by stencilFaces()): a filament spread narrower than the body it hangs from. Every stencil then
  /// spans the widest one's faces, a narrower marker's weights centred in it with zeros around, so
  /// spread, interpolate and gram treat all markers alike (a marker keeps the widest kernel's
  /// distance from the walls). `kernel_scale` is then unused.
  void locate(const fluid::MacGrid2& grid, Kernel kernel, std::span<const fluid::Vec2> positions_m,
              int kernel_scale = 1, std::span<const int> marker_scales = {});

  /// ADDS Σ_k F_k delta_h(x_face − X_k) into the face field; delta_h = phi(dx)phi(dy)/dx².
  /// Forces are per metre of depth (N/m, 2-D), so the density is N/m³.
  /// Throws std::invalid_argument if forces_n_per_m.size() != markerCount() or the field's
  /// shape is not that of the located grid's faces.
  void spread(std::span<const fluid::Vec2> forces_n_per_m, fluid::FaceVectorField2& force_density_n_per_m3) const;

  /// U_k = Σ_faces u(face) phi phi (the weights sum to 1). Overwrites velocities_m_per_s.
  /// Throws std::invalid_argument if velocities_m_per_s.size() != markerCount() or the grid is
  /// not the shape and cell size that locate() saw.
  void interpolate(const fluid::MacGrid2& grid, std::span<fluid::Vec2> velocities_m_per_s) const;

  int markerCount() const { return static_cast<int>(u_stencils_.size()); }

  /// The Gram matrix of the located stencils, G(2k + c, 2l + c) = Σ_faces w_k w_l on the faces of
  /// component c (x: u faces, y: v faces), 0 between components: interpolate(spread(F)) = G F / dx².
  /// Overwrites `gram` (2 markers × 2 markers). Kernels are separable, so each entry is a product
  /// of two 1-D overlaps.
  void gram(Eigen::MatrixXd& gram) const;
  /// The same scaled by `scale`, sparse: only the overlapping stencils (overwrites `out`).
  void gram(double scale, Eigen::SparseMatrix<double>& out) const;
  /// out = G x without forming G (x and out numbered as G, 2 · marker + component): x spread with
  /// the stencils' weights onto a patch of faces just covering them, and read back through the
  /// same weights. Equal to gram(1.0, G) · x up to rounding (the same products, summed face by face
  /// instead of marker pair by marker pair). `patch` is scratch, kept between calls to reuse its
  /// storage. Why: the semi-implicit coupling's refinement sweeps need M x every step but G itself
  /// only when they refactor (ib/coupling.cpp), and forming G is costly.
  void applyGram(std::span<const double> x, std::span<double> out, std::vector<double>& patch) const;

  /// The kernel of the last locate() (bilinear before the first).
  Kernel kernel() const { return kernel_; }
  /// The stretch of the last locate() (1 before the first; the widest with marker_scales) and its
  /// stencil width in faces per axis.
  int kernelScale() const { return scale_; }
  int stencilFaces() const { return support_; }
  /// Stencil of marker k on u faces (x components) and on v faces (y components).
  const FaceStencil& uStencil(int marker) const { return u_stencils_.at(static_cast<std::size_t>(marker)); }
  const FaceStencil& vStencil(int marker) const { return v_stencils_.at(static_cast<std::size_t>(marker)); }

 private:
  Kernel kernel_ = Kernel::bilinear;
  int scale_ = 1;
  int support_ = 2;            // stencil faces per axis: scale_ · kernelSupportCells(kernel_)
  int nx_ = 0;                 // cells of the located grid
  int ny_ = 0;
  double dx_m_ = 0.0;          // its cell size
  double inv_cell_area_per_m2_ = 0.0;  // 1 / dx²
  std::vector<FaceStencil> u_stencils_;
  std::vector<FaceStencil> v_stencils_;
};

}  // namespace creaturelab::ib
