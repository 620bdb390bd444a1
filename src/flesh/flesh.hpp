#pragma once
// The flesh of Lentine et al. 2010 §7.1-7.2: a deformable triangle mesh around the skeleton
// (flesh_mesh.hpp) with stretch springs on its edges and a zero-length binding spring from each vertex
// to its anchor on the skeleton, integrated "using fully implicit springs ... for stability": linearised
// backward Euler after Baraff & Witkin, "Large steps in cloth simulation", SIGGRAPH 1998, Eq. 15-16,
//   (M - h df/dv - h^2 df/dx) dv = h (f0 + h df/dx v0),   v1 = v0 + dv,   x1 = x0 + h v1,
// solved by conjugate gradients. The edge springs, their Jacobians and the flesh's weight come from
// the project's spring engine (springs::System, with compressed edges' transverse stiffness clamped
// as springs::ImplicitEuler does, so that the matrix stays positive definite).
//
// The binding force on vertex i is f_i = -k_i (x_i - p_i(t)) - c_i (v_i - w_i), p_i the anchor and
// w_i its velocity. Over a step the anchor is taken to move on with its velocity at the step's start,
// p_i(t + h) = p_i + h w_i (the skeleton steps after the flesh), so the binding is linear in
// (x1, v1) and its backward Euler step is exact:
//   f_i(x1, v1) = f_i(x0, v0) - h k_i (v0 - w_i) - (c_i + h k_i) dv_i.
// Its reaction -f_i(x1, v1) goes to the anchor's body for the skeleton's step, so the flesh's
// momentum change h sum f_i (+ external forces) is exactly what the bodies lose: linear momentum is
// conserved to the linear solve's tolerance. The flesh is implicit, the skeleton explicit
// (partitioned): stable for any flesh stiffness on a held or driven skeleton; a free body much lighter
// than the flesh bound to it is limited by MuJoCo's explicit step, h < 2 / omega with omega^2 the
// binding's total stiffness over the body's mass.
//
// A coupled step, in this order:
//   1. the fluid adds its forces to externalForces_n() (and to the bodies' applied forces);
//   2. step(skeleton, h): the flesh moves and adds its reactions to the bodies' applied forces;
//   3. skeleton.step(), then the caller clears the applied forces.
// Deterministic, no I/O.
#include <vector>

#include <Eigen/Core>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "flesh/flesh_mesh.hpp"
#include "flesh/flesh_params.hpp"
#include "rigid/rigid_data.hpp"
#include "springs/system.hpp"

namespace creaturelab::flesh {

// What the last step did.
struct FleshStepSummary {
  int cg_iterations = 0;
  double cg_relative_residual = 0;  // |A dv - b| / |b| (Eigen's estimate)
  bool cg_converged = true;
  Eigen::Vector3d binding_impulse_on_flesh_ns = Eigen::Vector3d::Zero();  // h sum_i f_i(x1, v1)
};

class Flesh {
 public:
  // The flesh of every moving geom of `model` at the reference configuration, at rest. Throws
  // std::invalid_argument with validate()'s message, or when the model has nothing to wrap.
  explicit Flesh(const rigid::RigidModel& model, const FleshParams& params = {});

  const FleshParams& params() const { return params_; }
  const FleshMesh& mesh() const { return mesh_; }
  int vertices() const { return mesh_.vertices(); }

  // Coupling hooks: vertex positions (m) and velocities (m/s), world frame, one column per vertex.
  const Eigen::Matrix3Xd& positions_m() const { return state_.x_m; }
  const Eigen::Matrix3Xd& velocities_m_per_s() const { return state_.v_m_per_s; }
  // Each vertex's share of the deformed surface (m^2): a marker's area for the fluid's coupling.
  void vertexAreas(Eigen::VectorXd& area_m2) const;
  // Forces (N) on the vertices for the next step, added by the caller (the fluid); step() uses them
  // and clears them.
  Eigen::Matrix3Xd& externalForces_n() { return external_n_; }

  // Replaces positions and velocities (3 x vertices each). Throws std::invalid_argument on a wrong size
  // or a non-finite entry.
  void setState(const Eigen::Matrix3Xd& x_m, const Eigen::Matrix3Xd& v_m_per_s);
  // Every vertex at its anchor, moving with it, at the skeleton's current pose (computes its kinematics).
  void placeOnSkeleton(rigid::RigidData& skeleton);

  // One backward Euler step of h seconds against the skeleton's current state (its kinematics are
  // recomputed first); adds the binding's reactions to the skeleton's applied forces. Does not step
  // the skeleton.
  void step(rigid::RigidData& skeleton, double h_s);
  const FleshStepSummary& lastStep() const { return summary_; }

  // Measures. Binding energy at the skeleton's pose as its kinematics last computed it.
  double kineticEnergy_j() const;
  double stretchEnergy_j() const;  // edges' 0.5 k (|l| - r)^2
  double bindingEnergy_j(const rigid::RigidData& skeleton) const;  // sum 0.5 k_i |x_i - p_i|^2
  Eigen::Vector3d linearMomentum_kg_m_per_s() const;
  // Binding spring of vertex i: stiffness k_i (N/m) and damping c_i (N s/m).
  double bindingStiffness_n_per_m(int i) const { return binding_k_[i]; }
  double bindingDamping_ns_per_m(int i) const { return binding_c_[i]; }

 private:
  // Stages of step().
  void forcesAtStart();                         // f0 (edges, weight, binding, external) and the Jacobians
  void rightHandSide(double h);                 // b = h (f0 + h df/dx v0)
  void assembleMatrix(double h);                // A = M - h df/dv - h^2 df/dx
  void solveVelocityChange();                   // CG: A dv = b
  void integrate(double h);                     // v1 = v0 + dv, x1 = x0 + h v1
  void bindingReactions(double h, rigid::RigidData& skeleton);

  FleshParams params_;
  FleshMesh mesh_;
  springs::System<3> edges_;  // edge springs and weight
  springs::State<3> state_;
  Eigen::VectorXd binding_k_, binding_c_;
  Eigen::Matrix3Xd external_n_;

  // Per-step work space.
  Eigen::Matrix3Xd anchor_m_, anchor_v_, force_n_, binding_force_n_;
  std::vector<Eigen::Triplet<double>> stiffness_, damping_, entries_;
  Eigen::SparseMatrix<double> a_;
  Eigen::VectorXd rhs_, dv_;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg_;
  FleshStepSummary summary_;
};

}  // namespace creaturelab::flesh
