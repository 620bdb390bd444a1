// Refinement on an earlier step's banded LU factors (ib/reused_banded_solve.hpp): a sequence of
// slowly drifting systems like the coupling's I − dt M K is solved to the tolerance with far fewer
// factorisations than systems; a jump in the matrix makes it factor anew and still solve; tolerance 0
// is the plain banded LU bit for bit; a singular matrix is reported; a matrix given by its product is
// formed only to factor. And BandedLU::multiply.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "ib/banded_lu.hpp"
#include "ib/reused_banded_solve.hpp"
#include "test_random.hpp"

namespace creaturelab::ib {
namespace {

using test::uniform;

constexpr int kN = 200, kBand = 12;

// A fixed random band B (entries in [-1, 1]) and the system I − s_k B with s_k drifting by `drift`
// per step: eigenvalues far from zero when the diagonal dominates, as in the coupling.
struct Drifting {
  std::vector<double> base;  // column-major band of B, kBand sub- and superdiagonals
  explicit Drifting(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    for (int j = 0; j < kN; ++j)
      for (int i = j - kBand; i <= j + kBand; ++i) base.push_back(uniform(rng, -1, 1));
  }
  void fill(BandedLU& a, double s) const {
    a.reset(kN, kBand, kBand);
    std::size_t k = 0;
    for (int j = 0; j < kN; ++j)
      for (int i = j - kBand; i <= j + kBand; ++i, ++k)
        if (i >= 0 && i < kN) a.at(i, j) = (i == j ? 30.0 : 0.0) - s * base[k];
  }
};

std::vector<double> rhs(int step) {
  std::vector<double> b(kN);
  for (int i = 0; i < kN; ++i) b[i] = std::sin(0.1 * i + 0.01 * step) + 0.3;
  return b;
}

double residual(const BandedLU& a, const std::vector<double>& x, const std::vector<double>& b) {
  std::vector<double> ax;
  a.multiply(x, ax);
  double r = 0, bn = 0;
  for (int i = 0; i < kN; ++i) r = std::max(r, std::abs(b[i] - ax[i])), bn = std::max(bn, std::abs(b[i]));
  return r / bn;
}

TEST(BandedLU, MultiplyMatchesTheEntries) {
  BandedLU a;
  a.reset(5, 1, 2);
  for (int j = 0; j < 5; ++j)
    for (int i = std::max(0, j - 2); i <= std::min(4, j + 1); ++i) a.at(i, j) = 10 * i + j + 1;
  std::vector<double> y;
  a.multiply({1, 2, 3, 4, 5}, y);
  for (int i = 0; i < 5; ++i) {
    double want = 0;
    for (int j = std::max(0, i - 1); j <= std::min(4, i + 2); ++j) want += (10 * i + j + 1) * (j + 1);
    EXPECT_EQ(y[i], want) << i;
  }
}

TEST(ReusedBandedSolve, SolvesDriftingSystemsToTheToleranceWithFewFactorisations) {
  const Drifting d(5);
  ReusedBandedSolve solver({1e-12, 4});
  BandedLU a;
  double worst = 0;
  for (int step = 0; step < 200; ++step) {
    d.fill(a, 1.0 + 1e-3 * step);
    std::vector<double> x = rhs(step);
    ASSERT_TRUE(solver.solve(a, x));
    worst = std::max(worst, residual(a, x, rhs(step)));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_EQ(solver.solves(), 200);
  EXPECT_LT(solver.factorizations(), 50);  // reused: 23 for these 200 systems, not one each
  EXPECT_GT(solver.sweeps(), 0);
}

// Given A by its product, the solve asks for A itself only on the steps it factors, and answers as
// the solve given A does: the same factorisations, and the same bits when the product is A's own.
TEST(ReusedBandedSolve, AnAppliedMatrixIsAssembledOnlyToFactor) {
  const Drifting d(5);
  ReusedBandedSolve given({1e-12, 4}), applied({1e-12, 4});
  BandedLU a;
  long assembled = 0;
  for (int step = 0; step < 200; ++step) {
    d.fill(a, 1.0 + 1e-3 * step);
    std::vector<double> x = rhs(step), y = rhs(step);
    ASSERT_TRUE(given.solve(a, x));
    ASSERT_TRUE(applied.solve(
        kN, [&](const std::vector<double>& v, std::vector<double>& av) { a.multiply(v, av); },
        [&]() -> const BandedLU& {
          ++assembled;
          return a;
        },
        y));
    ASSERT_EQ(x, y) << step;
  }
  EXPECT_EQ(assembled, applied.factorizations());
  EXPECT_EQ(applied.factorizations(), given.factorizations());
  EXPECT_LT(assembled, 50);
}

TEST(ReusedBandedSolve, AJumpInTheMatrixFactorsAnewAndStillSolves) {
  const Drifting d(7);
  ReusedBandedSolve solver;
  BandedLU a;
  d.fill(a, 1.0);
  std::vector<double> x = rhs(0);
  ASSERT_TRUE(solver.solve(a, x));
  const long before = solver.factorizations();
  d.fill(a, 14.0);  // far from the factored matrix: refinement diverges or stalls
  x = rhs(1);
  ASSERT_TRUE(solver.solve(a, x));
  EXPECT_EQ(solver.factorizations(), before + 1);
  EXPECT_LT(residual(a, x, rhs(1)), 1e-11);
}

TEST(ReusedBandedSolve, ToleranceZeroIsThePlainBandedLUBitForBit) {
  const Drifting d(9);
  ReusedBandedSolve solver({0.0, 4});
  BandedLU a, plain;
  for (int step = 0; step < 5; ++step) {
    d.fill(a, 1.0 + 1e-3 * step);
    d.fill(plain, 1.0 + 1e-3 * step);
    std::vector<double> x = rhs(step), y = rhs(step);
    ASSERT_TRUE(solver.solve(a, x));
    ASSERT_TRUE(plain.factor());
    plain.solve(y);
    EXPECT_TRUE(x == y) << step;
  }
  EXPECT_EQ(solver.factorizations(), 5);
}

TEST(ReusedBandedSolve, ASingularMatrixIsReported) {
  BandedLU a;
  a.reset(4, 1, 1);  // all zero
  std::vector<double> b{1, 2, 3, 4};
  ReusedBandedSolve solver;
  EXPECT_FALSE(solver.solve(a, b));
}

}  // namespace
}  // namespace creaturelab::ib
