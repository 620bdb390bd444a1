#pragma once

namespace creaturelab::fluid {

/// Outcome of a linear solve (iterative or direct).
struct LinearSolveReport {
  int iterations = 0;              ///< 0 for direct solves
  double relative_residual = 0.0;  ///< ‖b − A x‖∞ / ‖b‖∞ at exit (0 when b = 0)
  bool converged = true;
};

}  // namespace creaturelab::fluid
