#include "springs/implicit_euler.hpp"

#include <algorithm>

namespace creaturelab::springs {

template <int D> void ImplicitEuler<D>::step(const System<D>& system, State<D>& s, const StepContext& ctx) {
  const double h = ctx.dt_s;
  const int n = system.particleCount();
  const int dofs = D * n;
  const auto& pinned = system.network().pinned;

  // Stage 1: forces and Jacobians at the start of the step.
  system.forces(s, ctx.t_s, f0_);
  stiffness_.clear();
  damping_.clear();
  system.addStiffnessTriplets(s, 1.0, stiffness_, /*clamp_compression=*/true);
  system.addDampingTriplets(s, 1.0, damping_);

  // Stage 2: eliminate pinned coordinates.
  reduced_.assign(dofs, -1);
  mass_of_free_.resize(dofs);
  int free_dofs = 0;
  for (int p = 0; p < n; ++p)
    for (int d = 0; d < D; ++d)
      if (!pinned[p]) {
        mass_of_free_[free_dofs] = system.network().mass_kg[p];
        reduced_[D * p + d] = free_dofs++;
      }
  if (free_dofs == 0) {
    s.x_m += h * s.v_m_per_s;
    return;
  }

  // Stage 3: right-hand side h (f0 + h df/dx v0) over free coordinates.
  rhs_.resize(free_dofs);
  const double* v0 = s.v_m_per_s.data();
  for (int r = 0; r < dofs; ++r)
    if (reduced_[r] >= 0) rhs_[reduced_[r]] = f0_.data()[r];
  for (const auto& t : stiffness_) {
    const int r = reduced_[t.row()];
    if (r >= 0) rhs_[r] += h * t.value() * v0[t.col()];
  }
  rhs_ *= h;

  // Stage 4: A = M - h df/dv - h^2 df/dx, then CG.
  assemble(h, free_dofs);
  cg_.setTolerance(cg_tolerance_);
  cg_.compute(a_);
  dv_.setZero(free_dofs);
  dv_ = cg_.solveWithGuess(rhs_, dv_);
  last_cg_iterations_ = static_cast<int>(cg_.iterations());
  last_cg_error_ = cg_.error();

  // Stage 5: v1 = v0 + dv, x1 = x0 + h v1.
  double* v = s.v_m_per_s.data();
  for (int r = 0; r < dofs; ++r)
    if (reduced_[r] >= 0) v[r] += dv_[reduced_[r]];
  s.x_m += h * s.v_m_per_s;
}

// Builds a_ from the mass diagonal and the triplets. Triplets whose row or column is pinned are
// dropped. The pattern (row, column sequence) is compared with the cached one; only if it
// changed is the matrix rebuilt with setFromTriplets.
template <int D> void ImplicitEuler<D>::assemble(double h, int free_dofs) {
  // Gather (row, col, value) in a fixed order: mass, damping, stiffness.
  const int n_mass = free_dofs;
  const size_t total = n_mass + damping_.size() + stiffness_.size();
  std::vector<int>& rows = pattern_rows_;
  std::vector<int>& cols = pattern_cols_;
  // Pass 1: does the pattern match the cached one?
  bool same = a_.rows() == free_dofs && slot_.size() == total;
  size_t m = 0;
  auto check = [&](int r, int c) {
    if (same && (rows[m] != r || cols[m] != c)) same = false;
    ++m;
  };
  if (same) {
    for (int i = 0; i < n_mass; ++i) check(i, i);
    for (const auto& t : damping_) check(reduced_[t.row()], reduced_[t.col()]);
    for (const auto& t : stiffness_) check(reduced_[t.row()], reduced_[t.col()]);
  }
  if (!same) {
    rows.clear();
    cols.clear();
    for (int i = 0; i < n_mass; ++i) rows.push_back(i), cols.push_back(i);
    for (const auto& t : damping_) rows.push_back(reduced_[t.row()]), cols.push_back(reduced_[t.col()]);
    for (const auto& t : stiffness_) rows.push_back(reduced_[t.row()]), cols.push_back(reduced_[t.col()]);
    std::vector<Eigen::Triplet<double>> skeleton;
    skeleton.reserve(total);
    for (size_t i = 0; i < total; ++i)
      if (rows[i] >= 0 && cols[i] >= 0) skeleton.emplace_back(rows[i], cols[i], 0.0);
    a_.resize(free_dofs, free_dofs);
    a_.setFromTriplets(skeleton.begin(), skeleton.end());
    a_.makeCompressed();
    slot_.assign(total, -1);
    for (size_t i = 0; i < total; ++i)
      if (rows[i] >= 0 && cols[i] >= 0) slot_[i] = static_cast<int>(&a_.coeffRef(rows[i], cols[i]) - a_.valuePtr());
  }
  // Pass 2: values.
  double* val = a_.valuePtr();
  std::fill(val, val + a_.nonZeros(), 0.0);
  m = 0;
  for (int i = 0; i < n_mass; ++i) val[slot_[m++]] += mass_of_free_[i];
  for (const auto& t : damping_) {
    if (slot_[m] >= 0) val[slot_[m]] -= h * t.value();
    ++m;
  }
  for (const auto& t : stiffness_) {
    if (slot_[m] >= 0) val[slot_[m]] -= h * h * t.value();
    ++m;
  }
}

template class ImplicitEuler<2>;
template class ImplicitEuler<3>;

}  // namespace creaturelab::springs
