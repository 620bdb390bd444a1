#pragma once
// Closed form of m x'' + c x' + k x = 0 with x(0) = x0, x'(0) = v0 (thesis Eq. 4.12), for the
// under-, critically and over-damped cases. The defaults are the oscillator kind's: 1 Hz with 1 kg.
#include <cmath>

namespace creaturelab::kinds {

struct DampedOscillator {
  double mass_kg = 1.0;
  double stiffness_n_per_m = 4.0 * M_PI * M_PI;
  double damping_ns_per_m = 0.1;
  double x0_m = 0.1;
  double v0_m_per_s = 0.0;

  template <class V>
  void describe(V& v) {
    v.real("mass_kg", mass_kg, "kg", 1e-12, 1e6, "oscillating mass");
    v.real("stiffness_n_per_m", stiffness_n_per_m, "N/m", 1e-12, 1e12, "spring constant k (default: 1 Hz with 1 kg)");
    v.real("damping_ns_per_m", damping_ns_per_m, "N*s/m", 0, 1e12, "viscous drag c (thesis Eq. 4.7), 0 = undamped");
    v.real("x0_m", x0_m, "m", -1e3, 1e3, "initial displacement from rest");
    v.real("v0_m_per_s", v0_m_per_s, "m/s", -1e3, 1e3, "initial velocity");
  }

  double omega0() const { return std::sqrt(stiffness_n_per_m / mass_kg); }
  double zeta() const { return damping_ns_per_m / (2.0 * std::sqrt(stiffness_n_per_m * mass_kg)); }

  // Displacement and velocity at time t.
  void at(double t_s, double& x_m, double& v_m_per_s) const {
    const double w0 = omega0(), z = zeta(), a = z * w0;  // a = c / 2m
    const double e = std::exp(-a * t_s);
    if (z < 1.0 - 1e-12) {
      const double wd = w0 * std::sqrt(1.0 - z * z);
      const double B = (v0_m_per_s + a * x0_m) / wd;
      const double c = std::cos(wd * t_s), s = std::sin(wd * t_s);
      x_m = e * (x0_m * c + B * s);
      v_m_per_s = e * ((-a * x0_m + B * wd) * c + (-a * B - x0_m * wd) * s);
    } else if (z > 1.0 + 1e-12) {
      const double r = w0 * std::sqrt(z * z - 1.0);
      const double l1 = -a + r, l2 = -a - r;
      const double c1 = (v0_m_per_s - l2 * x0_m) / (l1 - l2), c2 = x0_m - c1;
      x_m = c1 * std::exp(l1 * t_s) + c2 * std::exp(l2 * t_s);
      v_m_per_s = c1 * l1 * std::exp(l1 * t_s) + c2 * l2 * std::exp(l2 * t_s);
    } else {
      const double B = v0_m_per_s + a * x0_m;
      x_m = e * (x0_m + B * t_s);
      v_m_per_s = e * (B - a * (x0_m + B * t_s));
    }
  }

  double energy(double x_m, double v_m_per_s) const {
    return 0.5 * mass_kg * v_m_per_s * v_m_per_s + 0.5 * stiffness_n_per_m * x_m * x_m;
  }
};

}  // namespace creaturelab::kinds
