#pragma once
// The model the integrators see. Thesis §4.2.1 (seeds/orb-webs-mehla-2005.txt): "the system or
// the model on which the solver operates is independent of the solver" — integrators only call
// forces()/accelerations() and, for implicit Euler, the Jacobian triplets below.
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "springs/network.hpp"

namespace creaturelab::springs {

// Extra force (wind, immersed-boundary coupling). It must ADD into force_n (D x particles,
// newtons), never overwrite it. Forces it puts on pinned particles are discarded.
template <int D>
using ExternalForce = std::function<void(double t_s, const State<D>&, Points<D>& force_n)>;

template <int D> class System {
 public:
  // Throws std::invalid_argument carrying Network::validate()'s message if the network is bad.
  explicit System(Network<D> network);

  const Network<D>& network() const { return network_; }
  int particleCount() const { return network_.particleCount(); }

  void setExternalForce(ExternalForce<D> f) { external_ = std::move(f); }
  bool hasExternalForce() const { return static_cast<bool>(external_); }

  // All forces (springs Eq. 4.14-4.15, bends, gravity Eq. 4.6, drag Eq. 4.7, external), newtons.
  // force_n is resized to D x particles and overwritten; pinned particles get zero.
  void forces(const State<D>& s, double t_s, Points<D>& force_n) const;
  // -grad(potentialEnergy): springs' Hooke term, bends and gravity only (no damping, drag or
  // external force); pinned particles get zero. The residual of static equilibrium.
  void conservativeForces(const State<D>& s, Points<D>& force_n) const;
  // M^-1 times forces(), fused into one pass (the integrators' hot path); pinned particles get 0.
  void accelerations(const State<D>& s, double t_s, Points<D>& acc_m_per_s2) const;
  // The same, but instead of storing the accelerations it calls finish(i, a_i) once per coordinate
  // i = D * particle + axis, in increasing i, with that coordinate's acceleration (m/s^2). An
  // integrator updates coordinate i inside finish, so the step is one flat (vectorisable) sweep
  // over memory instead of three. finish may change s's position and velocity at coordinate i
  // (all pairwise and external forces are summed before the first call); `scratch` receives the
  // raw forces.
  template <class Finish>
  void accelerationsThen(const State<D>& s, double t_s, Points<D>& scratch, Finish&& finish) const;

  // 1/m per particle, 0 for pinned particles (so "a = inv_mass * f" leaves them still).
  const Eigen::VectorXd& inverseMassPerKg() const { return inv_mass_per_kg_; }

  double kineticEnergy(const State<D>& s) const;     // sum 0.5 m |v|^2 over all particles, joules
  double elasticEnergy(const State<D>& s) const;     // springs 0.5 k (|l|-r)^2 + bends 0.5 kb (theta-theta0)^2
  double gravityEnergy(const State<D>& s) const;     // -sum m g . x (zero at x = 0), joules
  double potentialEnergy(const State<D>& s) const;   // elastic + gravity, joules

  // Jacobians for implicit Euler / Newton, appended as triplets in (D*particle + axis) numbering.
  // Rows of pinned particles are left out (their force is identically zero); their columns are kept.
  //
  // scale * df/dx of the conservative forces (springs' Hooke term and bends) = -scale * Hessian of
  // elasticEnergy. The position dependence of spring damping (a term in v, non-symmetric) is left
  // out, as in Baraff & Witkin 1998 §5; the external force is treated as explicit (not differentiated).
  // clamp_compression = true makes -df/dx positive semi-definite, which the conjugate-gradient solve
  // of implicit Euler needs: the transverse term k (1 - r/|l|) of a compressed spring (negative) is
  // set to 0, and bends keep only their Gauss-Newton part kb grad(theta) grad(theta)^T.
  // clamp_compression = false gives the true Jacobian (Newton for static equilibrium).
  void addStiffnessTriplets(const State<D>& s, double scale, std::vector<Eigen::Triplet<double>>& out,
                            bool clamp_compression) const;
  // scale * df/dv: spring damping -k_d u u^T per spring (Eq. 4.14) and drag -k_d I (Eq. 4.7).
  void addDampingTriplets(const State<D>& s, double scale, std::vector<Eigen::Triplet<double>>& out) const;

 private:
  // Springs and bends into force_n (overwritten), no unary forces, no pinning.
  void internalForces(const State<D>& s, Points<D>& force_n) const;

  Network<D> network_;
  Eigen::VectorXd inv_mass_per_kg_;
  // Per coordinate (D * particle + axis), so the acceleration pass is one flat loop:
  std::vector<double> inv_mass_per_coord_;  // 1/m, 0 when pinned
  std::vector<double> gravity_per_coord_;   // g, 0 when pinned
  bool any_spring_damping_ = false;
  ExternalForce<D> external_;
};

template <int D>
template <class Finish>
void System<D>::accelerationsThen(const State<D>& s, double t_s, Points<D>& scratch, Finish&& finish) const {
  internalForces(s, scratch);
  if (external_) external_(t_s, s, scratch);
  const int m = D * particleCount();
  const double drag = network_.drag_ns_per_m;
  const double* inv_m = inv_mass_per_coord_.data();
  const double* g = gravity_per_coord_.data();
  const double* v = s.v_m_per_s.data();
  const double* f = scratch.data();
  // a = (f + m g - drag v) / m  (Eq. 4.4, 4.6, 4.7); pinned coordinates have 1/m = 0 and g = 0.
  for (int i = 0; i < m; ++i) finish(i, inv_m[i] * (f[i] - drag * v[i]) + g[i]);
}

extern template class System<2>;
extern template class System<3>;

}  // namespace creaturelab::springs
