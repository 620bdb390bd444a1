#pragma once
// Static equilibrium of a spring network: the rest shape a long damped run settles to (thesis
// §5.1, the strand "settled down to its final state"), found directly by minimising the total
// potential energy (springs + bends + gravity + the constant force of System::setConstantForce) over
// the free particles' positions.
// Newton's method on the true Hessian (sparse Eigen::SimplicialLDLT) with a backtracking
// (Armijo) line search on energy; when LDLT fails or its direction is not a descent direction the
// step is taken from the Hessian with compressed springs' transverse stiffness clamped to 0 (positive
// semi-definite), plus mu I with mu raised until it is positive definite (Levenberg-style).
// Stops when max |force| on a free particle coordinate <= gradient_tolerance_n.
// The ExternalForce is not included (it may depend on time and velocity); a constant one belongs in
// System::setConstantForce.
#include "springs/system.hpp"

namespace creaturelab::springs {

struct EquilibriumOptions {
  double gradient_tolerance_n = 1e-12;  // newtons, on the largest residual force component
  int max_iterations = 200;
};

struct EquilibriumResult {
  bool converged = false;
  int iterations = 0;
  double max_residual_force_n = 0;  // largest |force component| on a free particle at the end
  double energy_j = 0;              // potentialEnergy at the end
};

// Solves positions in place (pinned particles are not moved) and sets every velocity to zero.
template <int D>
EquilibriumResult solveStaticEquilibrium(const System<D>& system, State<D>& s, const EquilibriumOptions& options = {});

}  // namespace creaturelab::springs
