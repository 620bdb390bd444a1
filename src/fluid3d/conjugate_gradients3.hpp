#pragma once
// Preconditioned conjugate gradients on a Stencil3 operator (diag x + off Σ neighbours), shared by the
// viscosity solve (Jacobi preconditioner) and the pressure solve (multigrid V-cycle).

#include <functional>
#include <vector>

#include "fluid3d/array3.hpp"
#include "fluid3d/stencil3.hpp"

namespace creaturelab::fluid3d {

// The iteration from a formed residual r = b − A x whose max norm is r_norm: until max|r| <= target
// or max_iterations steps. precondition() sets z from r; s and as are workspace. Updates x, r and
// r_norm; returns the steps taken.
int conjugateGradients3(const Stencil3& stencil, double diag, double off, double target, int max_iterations,
                        const std::function<void()>& precondition, Array3& x, Array3& r, double& r_norm, Array3& z,
                        Array3& s, Array3& as, std::vector<double>& per_slab, WorkerPool* pool);

}  // namespace creaturelab::fluid3d
