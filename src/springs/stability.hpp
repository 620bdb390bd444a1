#pragma once
// Stable explicit time steps for a spring network: an upper bound on its highest natural
// frequency times the stability interval of each integrator on the damped oscillator.
// The thesis calls this the Courant condition (Mehla 2005 §4.2: "dt must be
// inversely proportional to the square root of the spring stiffness").
#include "springs/integrator.hpp"
#include "springs/network.hpp"

namespace creaturelab::springs {

// Upper bound on the highest natural frequency sqrt(lambda_max(M^-1 K)), radians per second, with K
// the stiffness (springs + bends) at state s and pinned particles removed. Each eigenvalue of
// M^-1 K lies in a Gershgorin disc; two versions of the theorem are evaluated and the smaller
// bound is returned:
//   scalar: max over free coordinates r of sum_c |K_rc| / m_r;
//   block (Feingold-Varga, D x D blocks per particle): max over free particles i of
//           (rho(K_ii) + sum_{j != i, free} ||K_ij||_2) / m_i.
// The scalar form is exact for axis-aligned grids, the block form for chains in any direction.
// One spring k to a pinned end gives sqrt(k/m); an interior node of a straight chain sqrt(4k/m)
// (the exact top of the infinite chain's spectrum).
template <int D> double estimateOmegaMaxRadPerS(const Network<D>& network, const State<D>& s);

// Lower and upper bounds on the damping ratio of the highest mode at omega_max:
//   low  = min over free particles of drag / (2 m omega_max)           (drag damps every mode)
//   high = max over free particles of (drag + 2 sum k_d) / (2 m omega_max)   (Gershgorin on M^-1 C)
struct DampingRatioBounds {
  double low;
  double high;
};
template <int D> DampingRatioBounds estimateDampingRatio(const Network<D>& network, double omega_max_rad_per_s);

// Largest omega*dt for which the integrator is stable on x'' + 2 zeta omega x' + omega^2 x = 0.
//   explicit Euler:   |1 + h lambda| <= 1  ->  2 zeta (zeta <= 1), 2 (zeta - sqrt(zeta^2 - 1)) above;
//                     0 when undamped: explicit Euler always gains energy without damping.
//   symplectic Euler: Jury test on its 2x2 step matrix  ->  2 (sqrt(1 + zeta^2) - zeta); 2 undamped.
//   RK4:              boundary of |R(z)| <= 1 along the eigenvalue ray, found numerically;
//                     2 sqrt(2) = 2.83 undamped.
//   implicit Euler:   +infinity (A-stable).
double stabilityLimitOmegaDt(IntegratorKind kind, double damping_ratio);

// safety * stabilityLimitOmegaDt / omega_max, seconds; +infinity for implicit Euler or omega_max = 0,
// 0 for explicit Euler without damping.
double autoStepS(IntegratorKind kind, double omega_max_rad_per_s, double damping_ratio, double safety = 0.5);

}  // namespace creaturelab::springs
