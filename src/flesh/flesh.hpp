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
// The binding force on vertex i is f_i = -k_i (x_i - p_i) - c_i (v_i - w_i), p_i its anchor and w_i
// the anchor's velocity, w_i = J_i u with J_i the anchor's Jacobian and u the skeleton's joint
// velocities (MuJoCo's qvel). Over a step the anchor moves with its velocity at the step's end,
// p_i(t + h) = p_i + h w_i(t + h) (backward Euler for the skeleton's positions too), so the binding is
// linear in the unknowns and, with g_i = c_i + h k_i,
//   f_i(t + h) = f_i - h k_i (v_i - w_i) - g_i (dv_i - J_i du).
// The skeleton's velocity change under the reactions, B du = -h sum_i J_i^T f_i(t + h), with B = M + h D
// (MuJoCo's Euler matrix: mass and joint damping), is solved together with the flesh's as one
// symmetric positive definite system (its energy norm is dv' A dv + du' B du + h sum g_i |dv_i - J_i du|^2):
//   [ A + h G      -h G J       ] [dv]   [ h (f0 + h df/dx v0 - h k (v0 - w0))          ]
//   [ -h J^T G     B + h J^T G J ] [du] = [ -h sum_i J_i^T (f_i - h k_i (v_i - w_i)) ],
// A the flesh's matrix above without the binding. So the flesh and the skeleton are implicit together:
// stable for any binding stiffness and any mass ratio. The skeleton's own forces (gravity, joints,
// fluid, actuators) stay MuJoCo's: du is only the prediction that makes the coupling implicit, and the
// reactions -f_i(t + h) are handed to the bodies for MuJoCo's step, which gives du back exactly when
// nothing else acts. The flesh's momentum change h sum f_i(t + h) (+ external forces) is then exactly
// what the bodies lose: linear momentum is conserved to the linear solve's tolerance.
// (FleshParams::implicit_skeleton = false keeps du = 0 in the solve: the bodies see the reactions
// explicitly, which is unstable for stiff binding on light bones.)
//
// A coupled step, in this order:
//   1. the fluid adds its forces to externalForces_n() (and to the bodies' applied forces);
//   2. step(skeleton, h): the flesh moves and adds its reactions to the bodies' applied forces;
//   3. skeleton.step(), then the caller clears the applied forces.
// Deterministic, no I/O.
#include <vector>

#include <Eigen/Core>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
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
  // the skeleton; h should be its time step (B uses the model's for the joint damping).
  void step(rigid::RigidData& skeleton, double h_s);
  const FleshStepSummary& lastStep() const { return summary_; }

  // The same step split for a caller that solves impulses on the vertices and on the skeleton's DOFs
  // together with it (the fluid's coupled solve, coupling3d/flesh_fluid_coupling3.hpp). beginStep assembles
  // the system above against the skeleton's current state (external forces included as they stand),
  // K y = b with y = (dv, du) over every DOF, those in held_dofs (MuJoCo qvel indices) of infinite mass: their
  // rows and columns of K are the identity's and their Jacobian columns zero, so du = 0 there; and factorises
  // K (sparse LDLT: solveStep is exact to round-off, so K⁻¹ is a fixed symmetric operator an outer solve can
  // use). An impulse J on the vertices (N s, per vertex) and the DOFs (N m s, generalised) adds (J_v, J_q) to b.
  // endStep(y) sets v1 = v0 + dv, x1 = x0 + h v1, adds the binding's reactions at the step's end to the
  // skeleton's applied forces and clears the external forces, as step() does. Needs implicit_skeleton.
  // Throws std::invalid_argument for a held DOF out of range, a wrong size or a failed factorisation.
  void beginStep(rigid::RigidData& skeleton, double h_s, const std::vector<int>& held_dofs);
  const Eigen::VectorXd& stepRightHandSide() const { return rhs_; }
  // The diagonal of K (vertex rows first).
  const Eigen::VectorXd& stepDiagonal() const { return diagonal_; }
  void solveStep(const Eigen::VectorXd& b, Eigen::VectorXd& y) const;
  // Body b's Jacobian at beginStep's state: 6 x DOFs, the linear velocity of its centre of mass then its
  // angular velocity (world), zero columns for the held DOFs; empty for a body without flesh.
  const Eigen::MatrixXd& bodyJacobian(int b) const { return body_jacobian_[b]; }
  void endStep(rigid::RigidData& skeleton, double h_s, const Eigen::VectorXd& y);

  // The binding springs' forces on the vertices (N, world, one column per vertex) at the last step's end,
  // f_i(t + h) above: their negatives, at the anchors, are what the bones felt from the flesh in that step.
  const Eigen::Matrix3Xd& bindingForces_n() const { return binding_force_n_; }

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
  void anchorJacobians(rigid::RigidData& skeleton);  // J_i and B (implicit_skeleton only)
  // The step's checks (time step; with solved_with_impulses, implicit_skeleton; the skeleton's and the external
  // forces' sizes), then the skeleton's kinematics and the anchors' states and Jacobians.
  void startStep(rigid::RigidData& skeleton, double h_s, bool solved_with_impulses);
  void forcesAtStart();                         // f0 (edges, weight, binding, external) and the Jacobians
  void rightHandSide(double h);                 // b = h (f0 + h df/dx v0), the skeleton's rows
  void assembleMatrix(double h);                // the system above
  void solveVelocityChange();                   // CG: dv and du
  void integrate(double h);                     // v1 = v0 + dv, x1 = x0 + h v1
  void bindingReactions(double h, rigid::RigidData& skeleton);

  FleshParams params_;
  FleshMesh mesh_;
  springs::System<3> edges_;  // edge springs and weight
  int model_bodies_;          // the skeleton's body count, to refuse another model's data
  springs::State<3> state_;
  Eigen::VectorXd binding_k_, binding_c_;
  Eigen::Matrix3Xd external_n_;

  // Per-step work space.
  int dofs_ = 0;    // the skeleton's, in the solve (0 when the skeleton is explicit)
  Eigen::Matrix3Xd anchor_m_, anchor_v_, force_n_, binding_force_n_;
  Eigen::MatrixXd anchor_jacobian_;   // 3 vertices x dofs: J_i stacked
  Eigen::MatrixXd euler_matrix_;      // B = M + h D, dofs x dofs
  std::vector<Eigen::MatrixXd> body_jacobian_;  // per body: 6 x dofs (linear at the centre of mass, angular)
  Eigen::VectorXd diagonal_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  std::vector<Eigen::Triplet<double>> stiffness_, damping_, entries_;
  Eigen::SparseMatrix<double> a_;
  Eigen::VectorXd rhs_, dv_;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg_;
  FleshStepSummary summary_;
};

}  // namespace creaturelab::flesh
