#include "coupling3d/transfer3.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace creaturelab::coupling3d {
namespace {

std::string markerName(std::size_t k, const Vec3& p) {
  std::ostringstream out;
  out.precision(6);
  out << "immersed-boundary marker " << k << " at (" << p[0] << ", " << p[1] << ", " << p[2] << ") m";
  return out.str();
}

int wrap(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace

void Transfer3::locate(const fluid3d::MacGrid3& grid, ib::Kernel kernel, std::span<const Vec3> positions_m) {
  stencils_.clear();
  if (grid.n[0] < 1 || grid.n[1] < 1 || grid.n[2] < 1 || !(grid.dx_m > 0))
    throw std::invalid_argument("immersed-boundary transfer: the grid has no cells or no positive cell size");
  kernel_ = kernel;
  support_ = ib::kernelSupportCells(kernel);
  n_ = grid.n;
  for (int a = 0; a < 3; ++a) {
    periodic_[a] = grid.periodic(a);
    extents_[a] = grid.faceExtents(a);
  }
  inv_cell_volume_per_m3_ = 1.0 / grid.cellVolume_m3();
  stencils_.resize(positions_m.size());
  const int half = support_ / 2 - 1;  // the stencil starts at floor(xs) − half
  for (std::size_t k = 0; k < positions_m.size(); ++k) {
    const Vec3& x = positions_m[k];
    for (int a = 0; a < 3; ++a) {  // component
      FaceStencil3& s = stencils_[k][a];
      for (int b = 0; b < 3; ++b) {  // axis
        // Position in face-index units: faces of component a sit at i dx along axis a, (i + ½) dx along the others.
        const double xs = x[b] / grid.dx_m - (a == b ? 0.0 : 0.5);
        const double f = std::floor(xs);
        const double first = f - half;
        // Along a walled axis: faces 1..n−1 for the normal component, cells 0..n−1 for the others.
        const double lo = a == b ? 1.0 : 0.0, hi = a == b ? grid.n[b] - 1.0 : grid.n[b] - 1.0;
        const bool fits = periodic_[b] ? std::isfinite(xs) && std::abs(xs) < 1e9
                                       : first >= lo && first + (support_ - 1) <= hi;
        if (!fits) {
          stencils_.clear();
          throw std::invalid_argument(markerName(k, x) +
                                      " is not finite, outside the fluid box or within the kernel's reach (" +
                                      std::to_string(support_ / 2) + " cells) of a wall");
        }
        s.start[b] = static_cast<int>(first);
        ib::kernelWeights_1d(kernel, xs - f, s.w[b]);
      }
    }
  }
}

void Transfer3::spread(std::span<const Vec3> forces_n, fluid3d::FaceField3& density) const {
  if (forces_n.size() != stencils_.size())
    throw std::invalid_argument("immersed-boundary spread: one force per located marker expected");
  for (int a = 0; a < 3; ++a) {
    fluid3d::Array3& f = density[a];
    const std::array<int, 3>& e = extents_[a];
    if (f.nx() != e[0] || f.ny() != e[1] || f.nz() != e[2])
      throw std::invalid_argument("immersed-boundary spread: the force field is not the located grid's shape");
    for (std::size_t k = 0; k < stencils_.size(); ++k) {
      const FaceStencil3& s = stencils_[k][a];
      const double value = forces_n[k][a] * inv_cell_volume_per_m3_;
      for (int c = 0; c < support_; ++c) {
        const int kk = periodic_[2] ? wrap(s.start[2] + c, n_[2]) : s.start[2] + c;
        const double vc = value * s.w[2][c];
        for (int b = 0; b < support_; ++b) {
          const int jj = periodic_[1] ? wrap(s.start[1] + b, n_[1]) : s.start[1] + b;
          const double vb = vc * s.w[1][b];
          for (int i = 0; i < support_; ++i) {
            const int ii = periodic_[0] ? wrap(s.start[0] + i, n_[0]) : s.start[0] + i;
            f(ii, jj, kk) += vb * s.w[0][i];
          }
        }
      }
    }
  }
}

void Transfer3::interpolate(const fluid3d::FaceField3& u, std::span<Vec3> out) const {
  if (out.size() != stencils_.size())
    throw std::invalid_argument("immersed-boundary interpolate: one velocity per located marker expected");
  for (int a = 0; a < 3; ++a) {
    const fluid3d::Array3& f = u[a];
    const std::array<int, 3>& e = extents_[a];
    if (f.nx() != e[0] || f.ny() != e[1] || f.nz() != e[2])
      throw std::invalid_argument("immersed-boundary interpolate: the velocity field is not the located grid's shape");
    for (std::size_t k = 0; k < stencils_.size(); ++k) {
      const FaceStencil3& s = stencils_[k][a];
      double sum = 0.0;
      for (int c = 0; c < support_; ++c) {
        const int kk = periodic_[2] ? wrap(s.start[2] + c, n_[2]) : s.start[2] + c;
        double plane = 0.0;
        for (int b = 0; b < support_; ++b) {
          const int jj = periodic_[1] ? wrap(s.start[1] + b, n_[1]) : s.start[1] + b;
          double row = 0.0;
          for (int i = 0; i < support_; ++i) {
            const int ii = periodic_[0] ? wrap(s.start[0] + i, n_[0]) : s.start[0] + i;
            row += s.w[0][i] * f(ii, jj, kk);
          }
          plane += s.w[1][b] * row;
        }
        sum += s.w[2][c] * plane;
      }
      out[k][a] = sum;
    }
  }
}

}  // namespace creaturelab::coupling3d
