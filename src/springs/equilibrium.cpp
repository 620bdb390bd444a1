#include "springs/equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/SparseCholesky>

namespace creaturelab::springs {

namespace {

template <int D> double maxFreeForce(const Points<D>& f) { return f.size() ? f.cwiseAbs().maxCoeff() : 0.0; }

}  // namespace

// Newton on U(x) = elastic + gravity energy over the free coordinates:
//   H p = f   (H = Hessian of U = -df/dx, f = -grad U),   x <- x + alpha p,
// alpha from backtracking until U(x + alpha p) <= U(x) - 1e-4 alpha f.p (Armijo). LDLT of an
// indefinite H succeeds but may give a non-descent p, so a step is accepted from LDLT only when all
// pivots are positive; otherwise H + mu I is factorised with mu = 1e-8 max|H_ii|, growing x10.
// Near the minimum U changes by less than its own rounding error, so a step that fails Armijo is
// still taken when it lowers the largest residual force.
template <int D>
EquilibriumResult solveStaticEquilibrium(const System<D>& system, State<D>& s, const EquilibriumOptions& options) {
  const Network<D>& net = system.network();
  const int n = net.particleCount();
  s.v_m_per_s.setZero(D, n);
  std::vector<int> reduced(D * n, -1);
  int free_dofs = 0;
  for (int p = 0; p < n; ++p)
    for (int d = 0; d < D; ++d)
      if (!net.pinned[p]) reduced[D * p + d] = free_dofs++;

  EquilibriumResult result;
  Points<D> f, f_trial;
  system.conservativeForces(s, f);
  result.max_residual_force_n = maxFreeForce<D>(f);
  double energy = system.potentialEnergy(s);
  std::vector<Eigen::Triplet<double>> full, reduced_triplets;
  Eigen::SparseMatrix<double> h(free_dofs, free_dofs), h_reg;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  Eigen::VectorXd rhs(free_dofs), p(free_dofs);
  State<D> trial = s;

  while (result.max_residual_force_n > options.gradient_tolerance_n && result.iterations < options.max_iterations &&
         free_dofs > 0) {
    ++result.iterations;
    // Stage 1: true Hessian over free coordinates.
    full.clear();
    system.addStiffnessTriplets(s, -1.0, full, /*clamp_compression=*/false);
    reduced_triplets.clear();
    for (const auto& t : full) {
      const int r = reduced[t.row()], c = reduced[t.col()];
      if (r >= 0 && c >= 0) reduced_triplets.emplace_back(r, c, t.value());
    }
    h.setFromTriplets(reduced_triplets.begin(), reduced_triplets.end());
    for (int r = 0; r < D * n; ++r)
      if (reduced[r] >= 0) rhs[reduced[r]] = f.data()[r];

    // Stage 2: Newton direction, regularised until it is a descent direction.
    ldlt.compute(h);
    bool ok = ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0;
    if (ok) p = ldlt.solve(rhs);
    double mu = 1e-8 * std::max(1e-300, h.diagonal().cwiseAbs().maxCoeff());
    for (int tries = 0; !ok && tries < 40; ++tries, mu *= 10) {
      Eigen::SparseMatrix<double> eye(free_dofs, free_dofs);
      eye.setIdentity();
      h_reg = h + mu * eye;
      ldlt.compute(h_reg);
      ok = ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0;
      if (ok) p = ldlt.solve(rhs);
    }
    if (!ok || !p.allFinite()) break;
    const double slope = -rhs.dot(p);  // dU/dalpha at alpha = 0, negative for descent

    // Stage 3: backtracking line search on energy.
    double alpha = 1.0;
    bool accepted = false;
    for (int ls = 0; ls < 60 && !accepted; ++ls, alpha *= 0.5) {
      trial.x_m = s.x_m;
      for (int r = 0; r < D * n; ++r)
        if (reduced[r] >= 0) trial.x_m.data()[r] += alpha * p[reduced[r]];
      const double e_trial = system.potentialEnergy(trial);
      if (e_trial <= energy + 1e-4 * alpha * slope) {
        accepted = true;
      } else if (ls == 0) {
        system.conservativeForces(trial, f_trial);
        if (maxFreeForce<D>(f_trial) < result.max_residual_force_n && std::abs(e_trial - energy) <= 1e-12 * std::abs(energy) + 1e-300)
          accepted = true;
      }
      if (accepted) {
        s.x_m = trial.x_m;
        energy = e_trial;
      }
    }
    if (!accepted) break;
    system.conservativeForces(s, f);
    result.max_residual_force_n = maxFreeForce<D>(f);
  }
  result.converged = result.max_residual_force_n <= options.gradient_tolerance_n;
  result.energy_j = energy;
  return result;
}

template EquilibriumResult solveStaticEquilibrium<2>(const System<2>&, State<2>&, const EquilibriumOptions&);
template EquilibriumResult solveStaticEquilibrium<3>(const System<3>&, State<3>&, const EquilibriumOptions&);

}  // namespace creaturelab::springs
