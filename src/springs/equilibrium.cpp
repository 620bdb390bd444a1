#include "springs/equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/SparseCholesky>

namespace creaturelab::springs {

namespace {

template <int D> double maxFreeForce(const Points<D>& f) { return f.size() ? f.cwiseAbs().maxCoeff() : 0.0; }

}  // namespace

// Newton on U(x) = elastic + gravity + constant-force energy over the free coordinates:
//   H p = f   (H = Hessian of U = -df/dx, f = -grad U),   x <- x + alpha p,
// alpha from backtracking until U(x + alpha p) <= U(x) - 1e-4 alpha f.p (Armijo). LDLT of an
// indefinite H succeeds but may give a non-descent p, so a step is accepted from LDLT only when all
// pivots are positive; otherwise H is replaced by its clamped (positive semi-definite) form, plus mu I
// if needed (stage 2 below).
// Near the minimum U changes by less than its own rounding error, so a step that fails Armijo is
// still taken when it lowers the largest residual force.
//
// Stages per iteration: assemble H (stage 1), factorise and solve (stage 2), line search (stage 3).
// Speed (tests/bench/bench_web.cpp, BM_StaticEquilibrium): H is stored without its exact zeros, so a
// planar network in its plane (every spring's block has zero x-z and y-z entries) factorises as two
// independent systems, in-plane and out-of-plane: on the default web L has 245,828 nonzeros instead of
// 448,710 and factorises in a quarter of the time of the full 3 x 3 block pattern. The fill-reducing ordering
// (AMD) and the symbolic analysis are done once and reused while the pattern stays the same;
// regularisation adds mu on the diagonal through SimplicialLDLT::setShift, which keeps the pattern
// (the diagonal is always stored).
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
  // Sized once: addStiffnessTriplets appends D x D blocks, four per spring and nine per bend.
  const size_t triplets = static_cast<size_t>(D * D) * (4 * net.springCount() + 9 * net.bendCount());
  full.reserve(triplets);
  reduced_triplets.reserve(triplets + free_dofs);
  Eigen::SparseMatrix<double> h(free_dofs, free_dofs);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  std::vector<int> analysed_outer, analysed_inner;  // pattern of the last symbolic analysis
  Eigen::VectorXd rhs(free_dofs), p(free_dofs);
  State<D> trial = s;

  // Hessian of U at s over the free coordinates into h, exact zeros left out, diagonal always present;
  // the symbolic analysis is redone only when the pattern changes.
  auto assemble = [&](bool clamp_compression) {
    full.clear();
    system.addStiffnessTriplets(s, -1.0, full, clamp_compression);
    reduced_triplets.clear();
    for (int r = 0; r < free_dofs; ++r) reduced_triplets.emplace_back(r, r, 0.0);
    for (const auto& t : full) {
      const int r = reduced[t.row()], c = reduced[t.col()];
      if (r >= 0 && c >= 0 && t.value() != 0) reduced_triplets.emplace_back(r, c, t.value());
    }
    h.setFromTriplets(reduced_triplets.begin(), reduced_triplets.end());
    const bool same_pattern =
        !analysed_outer.empty() &&
        std::equal(analysed_outer.begin(), analysed_outer.end(), h.outerIndexPtr(), h.outerIndexPtr() + free_dofs + 1) &&
        static_cast<long>(analysed_inner.size()) == h.nonZeros() &&
        std::equal(analysed_inner.begin(), analysed_inner.end(), h.innerIndexPtr());
    if (!same_pattern) {
      ldlt.analyzePattern(h);
      analysed_outer.assign(h.outerIndexPtr(), h.outerIndexPtr() + free_dofs + 1);
      analysed_inner.assign(h.innerIndexPtr(), h.innerIndexPtr() + h.nonZeros());
    }
  };
  // Factorises h + shift I and solves for p; true when every pivot is positive (p is a descent direction).
  auto solveShifted = [&](double shift) {
    ldlt.setShift(shift);
    ldlt.factorize(h);
    const bool ok = ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0;
    if (ok) p = ldlt.solve(rhs);
    return ok;
  };

  while (result.max_residual_force_n > options.gradient_tolerance_n && result.iterations < options.max_iterations &&
         free_dofs > 0) {
    ++result.iterations;
    for (int r = 0; r < D * n; ++r)
      if (reduced[r] >= 0) rhs[reduced[r]] = f.data()[r];
    // Stages 1-2: Newton direction from the true Hessian; where that is not positive definite (springs
    // in compression, far from equilibrium), from the Hessian with the compressed springs' negative
    // transverse stiffness clamped to 0 (positive semi-definite, as implicit Euler uses), shifted by
    // mu = 1e-8 max|H_ii| (x10 each try) until positive definite. Rejected: shifting the true Hessian
    // alone (the previous rule); with a mu large enough to mask the negative curvature the step is
    // nearly steepest descent, and the softened webs of spring_constants.toml took 180 to over 200
    // iterations instead of 36 and 72.
    assemble(/*clamp_compression=*/false);
    bool ok = solveShifted(0.0);
    if (!ok) {
      assemble(/*clamp_compression=*/true);
      double mu = 1e-8 * std::max(1e-300, h.diagonal().cwiseAbs().maxCoeff());
      ok = solveShifted(0.0);
      for (int tries = 0; !ok && tries < 40; ++tries, mu *= 10) ok = solveShifted(mu);
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
