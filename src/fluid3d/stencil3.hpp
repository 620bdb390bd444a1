#pragma once
// Seven-point operators on the 3-D MAC grid, written once for the pressure (cells) and the
// viscosity (each velocity component) as neighbour tables per axis.
//
// Along each axis every sample m has a lower and an upper neighbour: an index into the same array
// and a factor. Inside the box the factor is 1; across a periodic side the index wraps; across a
// wall the neighbour is a ghost half a cell (or one face) beyond, written as factor · (the sample
// itself) (ghost values of Griebel et al. 1998, ch. 3, as in fluid/boundary2.hpp):
//   pressure at a solid wall or an inflow side   ghost = +self   (∂p/∂n = 0)
//   pressure at an open side       ghost = −self   (p = 0 on the side)
//   tangential velocity, free-slip or open   ghost = +self   (∂u_t/∂n = 0)
//   tangential velocity, no-slip or inflow   ghost = −self   (u_t = 0 on the side)
//   normal velocity next to a solid wall's face   factor 0 (that face is known: zero, or an inflow
//                                                  side's speed, which diffusion3 adds to the right side)
//   normal velocity beyond an open side's face    ghost = +self   (∂u_n/∂n = 0)
// A solid wall's (or inflow side's) own normal faces are not unknowns: operators leave them zero.
// With Σ_nb f x_nb the sum over the six neighbours, the operators are
//   y = diag · x + off · Σ_nb f x_nb     (pressure matrix A: diag 6, off −1; the discrete
//                                         Laplacian times dx²: diag −6, off 1).

#include <array>
#include <vector>

#include "fluid3d/array3.hpp"
#include "fluid3d/fluid_params3.hpp"
#include "fluid3d/parallel3.hpp"

namespace creaturelab::fluid3d {

/// Neighbour table along one axis of an array of `size` samples.
struct AxisStencil3 {
  int size = 0;
  std::vector<int> lo, hi;                 ///< neighbour indices
  std::vector<double> lo_factor, hi_factor;
  std::vector<unsigned char> unknown;      ///< 0 on a solid wall's normal face
  int plain_begin = 0, plain_end = 0;      ///< a run of samples with neighbours m ± 1, factor 1, unknown
};

/// Tables along x, y, z of one array.
struct Stencil3 {
  std::array<AxisStencil3, 3> axis;
  std::array<int, 3> extents() const { return {axis[0].size, axis[1].size, axis[2].size}; }
};

/// Pressure at cell centres, n cells along each axis.
Stencil3 pressureStencil(const std::array<int, 3>& cells, const Boundaries3& sides);
/// Velocity component a (the faces normal to axis a) for the viscosity.
Stencil3 velocityStencil(int a, const std::array<int, 3>& cells, const Boundaries3& sides);

/// y = diag · x + off · Σ_nb f x_nb on the unknowns; y = 0 on known samples.
void applyStencil(const Stencil3& s, double diag, double off, const Array3& x, Array3& y, WorkerPool* pool);
/// The diagonal of that operator: diag + off · Σ (factors of ghost neighbours that are the sample itself);
/// 1 on known samples (so that a Jacobi step leaves them alone).
void stencilDiagonal(const Stencil3& s, double diag, double off, Array3& d);

// Vector operations over whole arrays, slab-parallel; sums in slab order (deterministic).
double dot3(const Array3& a, const Array3& b, WorkerPool* pool, std::vector<double>& per_slab);
double maxAbs3(const Array3& a, WorkerPool* pool, std::vector<double>& per_slab);
double sum3(const Array3& a, WorkerPool* pool, std::vector<double>& per_slab);
/// y += s x.
void axpy3(double s, const Array3& x, Array3& y, WorkerPool* pool);
/// y = x + s y.
void xpay3(const Array3& x, double s, Array3& y, WorkerPool* pool);
/// a −= c (removes a constant).
void subtractConstant3(double c, Array3& a, WorkerPool* pool);

}  // namespace creaturelab::fluid3d
