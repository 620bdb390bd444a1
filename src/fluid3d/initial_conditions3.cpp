#include "fluid3d/initial_conditions3.hpp"

#include <cmath>

namespace creaturelab::fluid3d {

std::array<double, 3> AbcFlow::velocity_m_per_s(const std::array<double, 3>& x, double t_s) const {
  const double k = wavenumber_per_m;
  const double decay = std::exp(-viscosity_m2_per_s * k * k * t_s);
  return {decay * (a_m_per_s * std::sin(k * x[2]) + c_m_per_s * std::cos(k * x[1])),
          decay * (b_m_per_s * std::sin(k * x[0]) + a_m_per_s * std::cos(k * x[2])),
          decay * (c_m_per_s * std::sin(k * x[1]) + b_m_per_s * std::cos(k * x[0]))};
}

std::array<double, 3> TaylorGreen3::velocity_m_per_s(const std::array<double, 3>& x, double t_s) const {
  const double k = wavenumber_per_m;
  const double a = amplitude_m_per_s * std::exp(-3.0 * viscosity_m2_per_s * k * k * t_s);
  const double sx = std::sin(k * x[0]), cx = std::cos(k * x[0]), sy = std::sin(k * x[1]), cy = std::cos(k * x[1]);
  const double cz = std::cos(k * x[2]);
  return {a * sx * cy * cz, -a * cx * sy * cz, 0.0};
}

void setAbcFlow(MacGrid3& grid, const AbcFlow& flow, double t_s) { setFlow(grid, flow, t_s); }

double maxAbcError_m_per_s(const MacGrid3& grid, const AbcFlow& flow, double t_s) {
  double m = 0.0;
  for (int a = 0; a < 3; ++a) {
    const Array3& u = grid.velocity_m_per_s[a];
    for (int k = 0; k < u.nz(); ++k)
      for (int j = 0; j < u.ny(); ++j)
        for (int i = 0; i < u.nx(); ++i) {
          const double e = std::fabs(u(i, j, k) - flow.velocity_m_per_s(grid.facePosition_m(a, i, j, k), t_s)[a]);
          if (!(e <= m)) m = e;
        }
  }
  return m;
}

}  // namespace creaturelab::fluid3d
