#pragma once
// The model the integrators see. Thesis §4.2.1 (Mehla 2005): "the system or
// the model on which the solver operates is independent of the solver" — integrators only call
// forces()/accelerations() and, for implicit Euler, the Jacobian triplets below.
#include <algorithm>
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

  // A constant force (D x particles, newtons): independent of position, velocity and time, so it is
  // conservative, with potential -sum_p f_p . x_p, and the static solve (equilibrium.hpp) includes it,
  // unlike the ExternalForce above. Example: the orb web's inward frame force (web/frame_forces.hpp).
  // It is the starting value of the force sum, so it costs no extra pass. Forces on pinned particles are
  // discarded. An empty matrix (the default) means none. Throws std::invalid_argument on a wrong size or
  // a non-finite entry.
  void setConstantForce(Points<D> force_n);
  const Points<D>& constantForce() const { return constant_force_n_; }

  // All forces (springs Eq. 4.14-4.15, bends, gravity Eq. 4.6, drag Eq. 4.7, constant, external), newtons.
  // force_n is resized to D x particles and overwritten; pinned particles get zero.
  void forces(const State<D>& s, double t_s, Points<D>& force_n) const;
  // -grad(potentialEnergy): springs' Hooke term, bends, gravity and the constant force (no damping, drag
  // or ExternalForce); pinned particles get zero. The residual of static equilibrium.
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
  // The same, a block at a time: finish_block(i0, count, a) is called with the accelerations of
  // coordinates i0 .. i0 + count - 1 in a[0 .. count), blocks in increasing i0, count <= kBlockCoordinates
  // (a block may split a particle's axes), after all forces are summed; it may change s at those
  // coordinates.
  // The caller's per-coordinate loop over a block can then be vectorised (RungeKutta4 does so).
  static constexpr int kBlockCoordinates = 256;
  template <class FinishBlock>
  void accelerationsInBlocks(const State<D>& s, double t_s, Points<D>& scratch, FinishBlock&& finish_block) const;

  // 1/m per particle, 0 for pinned particles (so "a = inv_mass * f" leaves them still).
  const Eigen::VectorXd& inverseMassPerKg() const { return inv_mass_per_kg_; }

  double kineticEnergy(const State<D>& s) const;     // sum 0.5 m |v|^2 over all particles, joules
  double elasticEnergy(const State<D>& s) const;     // springs 0.5 k (|l|-r)^2 + bends 0.5 kb (theta-theta0)^2
  double gravityEnergy(const State<D>& s) const;     // -sum m g . x (zero at x = 0), joules
  double constantForceEnergy(const State<D>& s) const;  // -sum f . x over free particles (zero at x = 0), joules
  double potentialEnergy(const State<D>& s) const;   // elastic + gravity + constant force, joules

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
  // The constant force plus springs and bends into force_n (overwritten); no gravity, drag or
  // ExternalForce, no pinning.
  // with_damping = false leaves out the springs' damping term (conservativeForces).
  void internalForces(const State<D>& s, Points<D>& force_n, bool with_damping = true) const;

  Network<D> network_;
  Eigen::VectorXd inv_mass_per_kg_;
  // Per coordinate (D * particle + axis), so the acceleration pass is one flat loop:
  std::vector<double> inv_mass_per_coord_;  // 1/m, 0 when pinned
  std::vector<double> gravity_per_coord_;   // g, 0 when pinned
  bool any_spring_damping_ = false;
  ExternalForce<D> external_;
  Points<D> constant_force_n_;  // D x particles, or empty
};

template <int D>
template <class Finish>
void System<D>::accelerationsThen(const State<D>& s, double t_s, Points<D>& scratch, Finish&& finish) const {
  internalForces(s, scratch);  // constant force + springs + bends
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

template <int D>
template <class FinishBlock>
void System<D>::accelerationsInBlocks(const State<D>& s, double t_s, Points<D>& scratch,
                                      FinishBlock&& finish_block) const {
  internalForces(s, scratch);  // constant force + springs + bends
  if (external_) external_(t_s, s, scratch);
  const int m = D * particleCount();
  const double drag = network_.drag_ns_per_m;
  alignas(64) double a[kBlockCoordinates];
  for (int i0 = 0; i0 < m; i0 += kBlockCoordinates) {
    const int count = std::min(m - i0, kBlockCoordinates);
    const double* inv_m = inv_mass_per_coord_.data() + i0;
    const double* g = gravity_per_coord_.data() + i0;
    const double* v = s.v_m_per_s.data() + i0;
    const double* f = scratch.data() + i0;
    // accelerationsThen's formula, into a local buffer that nothing else can alias (so it vectorises).
    for (int j = 0; j < count; ++j) a[j] = inv_m[j] * (f[j] - drag * v[j]) + g[j];
    finish_block(i0, count, static_cast<const double*>(a));
  }
}

extern template class System<2>;
extern template class System<3>;

}  // namespace creaturelab::springs
