#include "ib/reused_banded_solve.hpp"

#include <algorithm>
#include <cmath>

namespace creaturelab::ib {

namespace {
double largest(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}
}  // namespace

bool ReusedBandedSolve::factorAndSolve(const BandedLU& a, std::vector<double>& b) {
  factors_ = a;
  ++factorizations_;
  have_factors_ = factors_.factor();
  if (!have_factors_) return false;
  factors_.solve(b);
  return true;
}

bool ReusedBandedSolve::solve(const BandedLU& a, std::vector<double>& b) {
  return solve(
      a.size(), [&](const std::vector<double>& x, std::vector<double>& ax) { a.multiply(x, ax); },
      [&]() -> const BandedLU& { return a; }, b);
}

bool ReusedBandedSolve::solve(int n, const Apply& apply, const Assemble& assemble, std::vector<double>& b) {
  ++solves_;
  if (!(policy_.tolerance > 0) || !have_factors_ || factors_.size() != n) return factorAndSolve(assemble(), b);
  const double limit = policy_.tolerance * largest(b);
  x_ = b;
  factors_.solve(x_);
  for (int sweep = 1; sweep <= policy_.max_sweeps; ++sweep) {
    ++sweeps_;
    apply(x_, ax_);
    r_.resize(b.size());
    for (std::size_t i = 0; i < b.size(); ++i) r_[i] = b[i] - ax_[i];
    if (largest(r_) <= limit) {
      b.swap(x_);
      return true;
    }
    if (sweep == policy_.max_sweeps) break;
    factors_.solve(r_);
    for (std::size_t i = 0; i < b.size(); ++i) x_[i] += r_[i];
  }
  return factorAndSolve(assemble(), b);
}

}  // namespace creaturelab::ib
