#include "fluid/initial_conditions2.hpp"

#include <cmath>

namespace creaturelab::fluid {
namespace {

// Fills u, v from a stream function sampled at the (nx + 1) × (ny + 1) corners.
template <typename Psi>
void setFromStreamFunction(MacGrid2& grid, Psi psi) {
  Array2 corner(grid.nx + 1, grid.ny + 1);
  for (int j = 0; j <= grid.ny; ++j) {
    for (int i = 0; i <= grid.nx; ++i) corner(i, j) = psi(i * grid.dx_m, j * grid.dx_m);
  }
  const double inv_dx = 1.0 / grid.dx_m;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i <= grid.nx; ++i) grid.u_m_per_s(i, j) = (corner(i, j + 1) - corner(i, j)) * inv_dx;
  }
  for (int j = 0; j <= grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) grid.v_m_per_s(i, j) = -(corner(i + 1, j) - corner(i, j)) * inv_dx;
  }
}

// ln cosh z without overflow.
double logCosh(double z) {
  const double a = std::abs(z);
  return a + std::log1p(std::exp(-2.0 * a)) - std::numbers::ln2;
}

}  // namespace

Vec2 taylorGreenVelocity_m_per_s(Vec2 position_m, double time_s, double width_m, double height_m,
                                   double amplitude_m_per_s, double kinematic_viscosity_m2_per_s) {
  const double kx = std::numbers::pi / width_m;
  const double ky = std::numbers::pi / height_m;
  const double decay =
      std::exp(-taylorGreenDecayRate_per_s(width_m, height_m, kinematic_viscosity_m2_per_s) * time_s);
  const double a = amplitude_m_per_s * decay;
  return {a * std::sin(kx * position_m.x) * std::cos(ky * position_m.y),
          -a * (kx / ky) * std::cos(kx * position_m.x) * std::sin(ky * position_m.y)};
}

double taylorGreenDecayRate_per_s(double width_m, double height_m, double kinematic_viscosity_m2_per_s) {
  const double kx = std::numbers::pi / width_m;
  const double ky = std::numbers::pi / height_m;
  return kinematic_viscosity_m2_per_s * (kx * kx + ky * ky);
}

void setTaylorGreen(MacGrid2& grid, const TaylorGreenVortex& vortex) {
  const double w = grid.width_m();
  const double h = grid.height_m();
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i <= grid.nx; ++i) {
      grid.u_m_per_s(i, j) =
          taylorGreenVelocity_m_per_s(grid.uPosition_m(i, j), 0.0, w, h, vortex.amplitude_m_per_s, 0.0).x;
    }
  }
  for (int j = 0; j <= grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      grid.v_m_per_s(i, j) =
          taylorGreenVelocity_m_per_s(grid.vPosition_m(i, j), 0.0, w, h, vortex.amplitude_m_per_s, 0.0).y;
    }
  }
}

void setVortexPair(MacGrid2& grid, const VortexPair& pair) {
  const double w = grid.width_m();
  const double h = grid.height_m();
  const double cx = pair.centre_x_fraction * w;
  const double cy = pair.centre_y_fraction * h;
  const double half = 0.5 * pair.separation_fraction * w;
  const double rc2 = (pair.core_radius_fraction * w) * (pair.core_radius_fraction * w);
  // Travel direction t = (cos θ, sin θ) and n = t turned by +90°. Each vortex is carried by
  // the other's velocity: the one at c + n d/2 turns counter-clockwise (+Γ), the one at
  // c − n d/2 clockwise (−Γ); both then move along t.
  const double nx_dir = -std::sin(pair.heading_rad);
  const double ny_dir = std::cos(pair.heading_rad);
  const double ax = cx + nx_dir * half, ay = cy + ny_dir * half;  // +Γ
  const double bx = cx - nx_dir * half, by = cy - ny_dir * half;  // −Γ
  const double k = pair.circulation_m2_per_s / (4.0 * std::numbers::pi);
  setFromStreamFunction(grid, [&](double x, double y) {
    const double ra2 = (x - ax) * (x - ax) + (y - ay) * (y - ay);
    const double rb2 = (x - bx) * (x - bx) + (y - by) * (y - by);
    return -k * std::log(ra2 + rc2) + k * std::log(rb2 + rc2);
  });
}

void setShearLayer(MacGrid2& grid, const ShearLayer& layer) {
  const double w = grid.width_m();
  const double h = grid.height_m();
  const double delta = layer.thickness_fraction * h;
  const double y0 = layer.centre_y_fraction * h;
  const double wave = 2.0 * std::numbers::pi * layer.perturbation_waves / w;
  const double eps_u = layer.perturbation_fraction * layer.speed_m_per_s;
  const double u_speed = layer.speed_m_per_s;
  setFromStreamFunction(grid, [&](double x, double y) {
    const double s = (y - y0) / delta;
    const double base = u_speed * delta * logCosh(s);  // ∂/∂y gives U tanh(s)
    const double g = std::exp(-0.25 * s * s);
    const double perturbation = layer.perturbation_waves > 0 ? eps_u / wave * std::cos(wave * x) * g : 0.0;
    return base + perturbation;
  });
}

void setRest(MacGrid2& grid) {
  grid.u_m_per_s.fill(0.0);
  grid.v_m_per_s.fill(0.0);
  grid.pressure_pa.fill(0.0);
}

}  // namespace creaturelab::fluid
