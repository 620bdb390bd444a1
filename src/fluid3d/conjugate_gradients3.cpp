#include "fluid3d/conjugate_gradients3.hpp"

namespace creaturelab::fluid3d {

int conjugateGradients3(const Stencil3& stencil, double diag, double off, double target, int max_iterations,
                        const std::function<void()>& precondition, Array3& x, Array3& r, double& r_norm, Array3& z,
                        Array3& s, Array3& as, std::vector<double>& per_slab, WorkerPool* pool) {
  precondition();
  s = z;
  double rho = dot3(r, z, pool, per_slab);
  as.resize(r.nx(), r.ny(), r.nz());
  int it = 0;
  while (r_norm > target && it < max_iterations) {
    ++it;
    applyStencil(stencil, diag, off, s, as, pool);
    const double alpha = rho / dot3(s, as, pool, per_slab);
    axpy3(alpha, s, x, pool);
    axpy3(-alpha, as, r, pool);
    r_norm = maxAbs3(r, pool, per_slab);
    if (r_norm <= target) break;
    precondition();
    const double rho_new = dot3(r, z, pool, per_slab);
    xpay3(z, rho_new / rho, s, pool);
    rho = rho_new;
  }
  return it;
}

}  // namespace creaturelab::fluid3d
