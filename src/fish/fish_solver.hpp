#pragma once
// The fish's time step (spec §2; thesis ch. 4). A step is a short list of named stages:
//   1. unitForces   Voigt units: n_ij = (c e + gamma e') / |r|,  G_i = sum_j n_ij r_ij
//   2. waterForce   F^w on the faces (water_force.hpp), at time t
//   3. assemble     A = M/dt + dt K,  K_ii = sum_j n_ij,  K_ij = -n_ij   (semi-implicit only)
//   4. solve        A V+ = F^w + (M/dt) V + G   by LDL^T (one n x n matrix for the x, y, z columns)
//   5. integrate    X+ = X + dt V+
// Derivation: the force on i at t + dt, with n_ij frozen at t, is
//   sum_j n_ij (r_ij + dt (v_j+ - v_i+)) = G_i - dt (K V+)_i,
// so M (V+ - V)/dt = F^w + G - dt K V+ is a linearly implicit Euler step in the units' secant
// stiffness. K's columns sum to zero and sum_i G_i = 0, so with no water sum_i m_i v_i is conserved
// exactly in exact arithmetic (the air experiment measures it in floating point).
//
// A is 23 x 23: a dense fixed-size LDL^T (Eigen::LDLT, diagonal pivoting) costs a few microseconds
// and allocates nothing; a sparse or skyline factorisation (Tu's choice) only pays off for larger n.
//
// The explicit schemes for comparison (stability experiment) use the same forces:
//   explicit_euler:   V+ = V + dt M^-1 (F^w + G),  X+ = X + dt V
//   symplectic_euler: V+ = V + dt M^-1 (F^w + G),  X+ = X + dt V+
// and, not the spec's, a linearly implicit Euler step in the units' full tangent (Baraff & Witkin
// 1998), to show what the spec's secant matrix leaves out (stability experiment):
//   tangent_implicit: (M/dt + dt K_t + D) V+ = F^w + G + (M/dt) V + D V,  X+ = X + dt V+,
//   K_t = c r^r^T + (c e / |r|)(I - r^r^T) and D = gamma r^r^T per unit on 3 x 3 blocks (3n x 3n,
//   not shared by x, y, z). The spec's K has only n_ij I, which is zero at rest length.
#include <array>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "fish/fish_model.hpp"
#include "fish/water_force.hpp"

namespace creaturelab::fish {

enum class Scheme { semi_implicit, explicit_euler, symplectic_euler, tangent_implicit };

struct FishState {
  NodeMatrix x_m;
  NodeMatrix v_m_per_s;
  std::array<double, kUnits> rest_m{};  // current rest lengths: muscles change theirs (motor.hpp)
  double time_s = 0;
  long step = 0;
};

// The fish at rest in its undeformed shape.
FishState restState(const FishModel& fish);

struct SolverParams {
  double dt_s = 0.002;  // ours (the [reimpl] 0.055 is for its soft units; see describe)
  Scheme scheme = Scheme::semi_implicit;
  WaterParams water;
  // Blow-up: a unit whose length leaves [1/(1 + s), 1 + s] times its undeformed length (our choice:
  // s = 2, i.e. three times longer or three times shorter), a non-finite value, or a lost positive
  // definiteness of A.
  double blowup_strain = 2.0;

  template <class V>
  void describe(V& v) {
    water.describe(v);
    v.real("dt_s", dt_s, "s", 1e-9, 100,
           "time step (ours: the [reimpl] 0.055 s is for its soft units; the calibrated body's stiffest vibration "
           "allows about 3 ms, 2 / w_max; studies/fish/convergence.toml)");
    v.choice("scheme", scheme,
             {{"semi_implicit", Scheme::semi_implicit}, {"explicit_euler", Scheme::explicit_euler},
              {"symplectic_euler", Scheme::symplectic_euler}, {"tangent_implicit", Scheme::tangent_implicit}},
             "time integrator (spec §2: semi-implicit Euler); the explicit ones and tangent_implicit (full tangent, "
             "not the spec's) for the stability comparison");
    v.real("blowup_strain", blowup_strain, "", 1e-3, 1e3,
           "a unit longer than (1 + this) or shorter than 1/(1 + this) times its undeformed length counts as a blow-up");
  }

  // "" or what is wrong, naming the parameter.
  std::string validate() const;
};

enum class StepStatus { ok, not_positive_definite, non_finite, overstretched };

struct StepReport {
  StepStatus status = StepStatus::ok;
  std::string cause;  // empty when ok: which unit or node, what value
};

class FishSolver {
 public:
  // Throws std::invalid_argument if the parameters are bad. Keeps a reference: `fish` must outlive it.
  FishSolver(const FishModel& fish, SolverParams params);

  // Advances s by one step (the stages above). On failure s is left at the last good state
  // (the stages write into scratch until the step is accepted) and the report names the cause.
  StepReport step(FishState& s);

  const SolverParams& params() const { return params_; }
  const FishModel& fish() const { return fish_; }

  // The stages, public so that a test can run one alone.
  void unitForces(const FishState& s);  // fills unitCoefficients() and unitForceSum()
  void waterForce(const FishState& s);  // fills waterForceN()
  void assemble();                      // fills matrix() from unitCoefficients()
  const std::array<double, kUnits>& unitCoefficients() const { return n_; }
  const NodeMatrix& unitForceSum() const { return g_; }
  const NodeMatrix& waterForceN() const { return fw_; }
  const Eigen::Matrix<double, kNodes, kNodes>& matrix() const { return a_; }

 private:
  StepReport checkState(const NodeMatrix& x, const NodeMatrix& v) const;
  StepReport solveTangent(const FishState& s, const NodeMatrix& force);  // fills v_next_

  const FishModel& fish_;
  SolverParams params_;
  Eigen::Matrix<double, kNodes, 1> mass_kg_;
  std::array<double, kUnits> rest0_m_{};  // undeformed lengths, for the blow-up check
  std::array<double, kUnits> n_{};
  NodeMatrix g_, fw_, x_next_, v_next_;
  Eigen::Matrix<double, kNodes, kNodes> a_;
  Eigen::LDLT<Eigen::Matrix<double, kNodes, kNodes>> ldlt_;
  Eigen::Matrix<double, 3 * kNodes, 3 * kNodes> a3_;  // tangent_implicit only
  Eigen::LDLT<Eigen::Matrix<double, 3 * kNodes, 3 * kNodes>> ldlt3_;
};

}  // namespace creaturelab::fish
