#pragma once
// Solves the semi-implicit coupling's banded systems, one per step, on an earlier step's LU factors.
//
// Why: the system I − dt M K (ib/coupling.hpp) changes little from one step to the next (markers move
// a few hundredths of a cell, the muscle tension a fraction of a percent), while factoring it anew
// every step is a large share of a 1 mm jellyfish step. Iterative refinement on the
// factors P of a nearby matrix (Golub & Van Loan, Matrix Computations, 4th ed., §3.5.3; here a
// preconditioned Richardson iteration, x ← x + P⁻¹ (b − A x)) converges by the factor ‖I − P⁻¹ A‖
// per sweep, small while P is recent. The system is factored anew when max_sweeps sweeps do not
// bring the residual ‖b − A x‖∞ under tolerance · ‖b‖∞, and the step is then solved with those
// fresh factors, as without reuse. So the answer is this step's system's to the tolerance, not an
// older one's; and U* only sets the implicit correction of the force (the markers move with the
// fluid whatever U* is, ib/coupling.hpp), so its error of 1e-8 relative is far below the step's.
// Tighter tolerances (1e-10, 1e-12) refactor on most steps and gain nothing; 1e-8 with six sweeps
// refactors rarely and leaves the swim unchanged to about 11 digits.
// Deterministic: whether to factor depends on the residuals alone, which the same inputs reproduce
// bit for bit. tolerance = 0 factors every step (the plain banded LU, bit for bit).
#include <functional>
#include <vector>

#include "ib/banded_lu.hpp"

namespace creaturelab::ib {

struct FactorReuse {
  double tolerance = 1e-8;  // ‖b − A x‖∞ / ‖b‖∞ accepted; 0: factor every step
  int max_sweeps = 6;       // solves with the old factors before factoring anew
};

class ReusedBandedSolve {
 public:
  explicit ReusedBandedSolve(FactorReuse policy = {}) : policy_(policy) {}
  /// Solves a x = b, b overwritten by x; `a` holds this step's matrix, not factored. False if a
  /// fresh factorisation meets an exactly zero pivot (a singular matrix).
  bool solve(const BandedLU& a, std::vector<double>& b);
  /// The same with A given by its product: apply(x, ax) sets ax = A x, and assemble() returns
  /// this step's A in a band, not factored; it is called only when the solve factors, so that a
  /// caller whose apply() is cheaper than forming A forms it only on those steps. n: A's size.
  using Apply = std::function<void(const std::vector<double>&, std::vector<double>&)>;
  using Assemble = std::function<const BandedLU&()>;
  bool solve(int n, const Apply& apply, const Assemble& assemble, std::vector<double>& b);
  long factorizations() const { return factorizations_; }
  long solves() const { return solves_; }
  long sweeps() const { return sweeps_; }

 private:
  bool factorAndSolve(const BandedLU& a, std::vector<double>& b);
  FactorReuse policy_;
  BandedLU factors_;
  bool have_factors_ = false;
  std::vector<double> x_, ax_, r_;
  long factorizations_ = 0, solves_ = 0, sweeps_ = 0;
};

}  // namespace creaturelab::ib
