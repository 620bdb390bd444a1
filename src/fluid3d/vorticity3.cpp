#include "fluid3d/vorticity3.hpp"

#include <cmath>

namespace creaturelab::fluid3d {

void FlowObservables3::update(const MacGrid3& grid) {
  const int nx = grid.n[0], ny = grid.n[1], nz = grid.n[2];
  for (int a = 0; a < 3; ++a) {
    padded_[a].fill(a, grid, grid.velocity_m_per_s[a], nullptr);
    velocity_[a].resize(nx, ny, nz);
    vorticity_[a].resize(nx, ny, nz);
  }
  vorticity_magnitude_.resize(nx, ny, nz);
  q_.resize(nx, ny, nz);
  const double per_dx = 1.0 / grid.dx_m;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int c[3] = {i, j, k};
        // Component a at the centre of cell c + shift (shift one step along one axis b ≠ a, or none).
        auto centred = [&](int a, int b, int shift) {
          int m[3] = {c[0], c[1], c[2]};
          if (b >= 0) m[b] += shift;
          const double lo = padded_[a].at(m[0], m[1], m[2]);
          m[a] += 1;
          return 0.5 * (lo + padded_[a].at(m[0], m[1], m[2]));
        };
        double g[3][3];  // g[a][b] = ∂u_a/∂x_b
        for (int a = 0; a < 3; ++a) {
          velocity_[a](i, j, k) = centred(a, -1, 0);
          for (int b = 0; b < 3; ++b) {
            if (b == a) {
              int m[3] = {c[0], c[1], c[2]};
              const double lo = padded_[a].at(m[0], m[1], m[2]);
              m[a] += 1;
              g[a][a] = (padded_[a].at(m[0], m[1], m[2]) - lo) * per_dx;
            } else {
              g[a][b] = (centred(a, b, 1) - centred(a, b, -1)) * (0.5 * per_dx);
            }
          }
        }
        const double wx = g[2][1] - g[1][2], wy = g[0][2] - g[2][0], wz = g[1][0] - g[0][1];
        vorticity_[0](i, j, k) = wx, vorticity_[1](i, j, k) = wy, vorticity_[2](i, j, k) = wz;
        vorticity_magnitude_(i, j, k) = std::sqrt(wx * wx + wy * wy + wz * wz);
        // ‖Ω‖² − ‖S‖² = Σ_ab (Ω_ab² − S_ab²) = −Σ_ab G_ab G_ba.
        double minus_trace = 0.0;
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) minus_trace -= g[a][b] * g[b][a];
        q_(i, j, k) = 0.5 * minus_trace;
      }
}

}  // namespace creaturelab::fluid3d
