// The banded LU of the semi-implicit coupling (ib/banded_lu.hpp) against Eigen's dense partial-pivot
// LU: random banded systems whose small diagonal forces row interchanges, narrow and wide bands,
// the edges (n = 1, a band wider than the matrix), and a singular matrix reported as such. And the
// reach (set_reach): multiply() over it bit for bit as over the band, reset() zeroing all that is not
// zero after a factor() or a write past it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "ib/banded_lu.hpp"
#include "test_random.hpp"
#include "support/dense_linalg.hpp"

namespace creaturelab::ib {
namespace {

using test::uniform;

// Fills both the banded and a dense copy of one random band matrix; the diagonal is small, so
// partial pivoting has to swap rows.
Eigen::MatrixXd fillRandom(BandedLU& lu, int n, int kl, int ku, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  lu.reset(n, kl, ku);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - ku); i <= std::min(n - 1, j + kl); ++i) {
      const double v = i == j ? uniform(rng, -0.05, 0.05) : uniform(rng, -1, 1);
      lu.at(i, j) = v;
      dense(i, j) = v;
    }
  return dense;
}

TEST(BandedLU, SolvesLikeDensePartialPivotLU) {
  struct Case {
    int n, kl, ku;
  };
  for (const Case c : {Case{1, 0, 0}, Case{7, 1, 1}, Case{40, 3, 5}, Case{40, 6, 2}, Case{120, 17, 17},
                       Case{30, 40, 40}}) {
    BandedLU lu;
    const Eigen::MatrixXd a = fillRandom(lu, c.n, c.kl, c.ku, 7 + c.n + c.kl);
    std::mt19937_64 rng(3);
    std::vector<double> b(c.n);
    Eigen::VectorXd bv(c.n);
    for (int i = 0; i < c.n; ++i) bv[i] = b[i] = uniform(rng, -1, 1);
    ASSERT_TRUE(lu.factor()) << c.n << " " << c.kl << " " << c.ku;
    lu.solve(b);
    const Eigen::VectorXd want = test::luSolve(a, bv);
    const Eigen::VectorXd got = Eigen::Map<Eigen::VectorXd>(b.data(), c.n);
    EXPECT_LT((a * got - bv).norm(), 1e-11 * bv.norm() * a.norm()) << c.n << " " << c.kl << " " << c.ku;
    EXPECT_LT((got - want).norm(), 1e-9 * want.norm()) << c.n << " " << c.kl << " " << c.ku;
  }
}

// Columns that reach less far than the band (as the jellyfish's do: 256 of 379 rows on average),
// with a small diagonal (row interchanges fill U) and a dominant one (none do): solve() runs each
// column over its factors' nonzero reach only.
TEST(BandedLU, RaggedColumnsSolveLikeDenseLU) {
  for (const double diagonal : {0.05, 40.0}) {
    const int n = 90, kl = 14, ku = 11;
    std::mt19937_64 rng(diagonal < 1 ? 21 : 22);
    BandedLU lu;
    lu.reset(n, kl, ku);
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (int j = 0; j < n; ++j) {
      const int up = static_cast<int>(rng() % (ku + 1)), down = static_cast<int>(rng() % (kl + 1));
      for (int i = std::max(0, j - up); i <= std::min(n - 1, j + down); ++i) {
        const double v = i == j ? uniform(rng, -diagonal, diagonal) + (diagonal > 1 ? diagonal : 0.0) : uniform(rng, -1, 1);
        lu.at(i, j) = v;
        a(i, j) = v;
      }
    }
    std::vector<double> b(n);
    Eigen::VectorXd bv(n);
    for (int i = 0; i < n; ++i) bv[i] = b[i] = uniform(rng, -1, 1);
    ASSERT_TRUE(lu.factor());
    lu.solve(b);
    const Eigen::VectorXd got = Eigen::Map<Eigen::VectorXd>(b.data(), n);
    const Eigen::VectorXd want = test::luSolve(a, bv);
    EXPECT_LT((a * got - bv).norm(), 1e-11 * bv.norm() * a.norm()) << "diagonal " << diagonal;
    EXPECT_LT((got - want).norm(), 1e-9 * want.norm()) << "diagonal " << diagonal;
  }
}

TEST(BandedLU, RefactoringTheSameMatrixIsBitwiseEqual) {
  BandedLU a, b;
  fillRandom(a, 60, 9, 9, 11);
  fillRandom(b, 60, 9, 9, 11);
  ASSERT_TRUE(a.factor());
  ASSERT_TRUE(b.factor());
  std::vector<double> x(60, 1.0), y(60, 1.0);
  a.solve(x);
  b.solve(y);
  EXPECT_TRUE(x == y);
}

TEST(BandedLU, ASingularMatrixIsReported) {
  BandedLU lu;
  lu.reset(5, 1, 1);
  for (int i = 0; i < 5; ++i) lu.at(i, i) = 1.0;
  lu.at(2, 2) = 0.0;  // column 2 is zero on and below the diagonal: no pivot
  lu.at(1, 2) = 3.0;
  EXPECT_FALSE(lu.factor());
}

// A matrix whose columns reach less far than the band, some entries in the reach exactly ±0, and
// column 5 empty; first and last get each column's reach.
void fillRagged(BandedLU& lu, int n, int kl, int ku, std::uint64_t seed, std::vector<int>& first,
                std::vector<int>& last) {
  std::mt19937_64 rng(seed);
  lu.reset(n, kl, ku);
  first.assign(n, 0);
  last.assign(n, -1);
  for (int j = 0; j < n; ++j) {
    if (j == 5) continue;
    const int up = static_cast<int>(rng() % (ku + 1)), down = static_cast<int>(rng() % (kl + 1));
    first[j] = std::max(0, j - up);
    last[j] = std::min(n - 1, j + down);
    for (int i = first[j]; i <= last[j]; ++i) {
      const int kind = static_cast<int>(rng() % 8);
      lu.at(i, j) = kind == 0 ? 0.0 : kind == 1 ? -0.0 : i == j ? 5.0 + uniform(rng, 0, 1) : uniform(rng, -1, 1);
    }
  }
}

std::vector<double> ones(int n) { return std::vector<double>(n, 1.0); }

TEST(BandedLU, MultiplyOverTheReachIsBitwiseThatOverTheBand) {
  const int n = 70, kl = 12, ku = 9;
  BandedLU lu;
  std::vector<int> first, last;
  fillRagged(lu, n, kl, ku, 5, first, last);
  std::mt19937_64 rng(8);
  std::vector<double> x(n), band, reach;
  for (double& v : x) v = uniform(rng, -1, 1);
  x[3] = -0.0;
  lu.multiply(x, band);
  lu.setReach(first, last);
  lu.multiply(x, reach);
  ASSERT_EQ(band.size(), reach.size());
  EXPECT_EQ(std::memcmp(band.data(), reach.data(), band.size() * sizeof(double)), 0);
}

// The reach counts for the matrix set before it: a write after setReach(), or a factor(), which
// fills the kl rows above the band, makes reset() zero all the storage.
TEST(BandedLU, ResetZeroesWritesPastTheReachAndTheFactors) {
  const int n = 50, kl = 8, ku = 6;
  std::vector<int> first(n), last(n);
  for (const bool factor : {false, true}) {
    BandedLU lu;
    if (factor) {
      fillRandom(lu, n, kl, ku, 9);  // a small diagonal: row interchanges fill the rows above the band
      for (int j = 0; j < n; ++j) first[j] = std::max(0, j - ku), last[j] = std::min(n - 1, j + kl);
      lu.setReach(first, last);
      ASSERT_TRUE(lu.factor());
    } else {
      fillRagged(lu, n, kl, ku, 9, first, last);
      lu.setReach(first, last);
      lu.at(5, 5) = 1.0;  // column 5's reach is empty
    }
    lu.reset(n, kl, ku);
    std::vector<double> y;
    lu.multiply(ones(n), y);
    EXPECT_TRUE(std::all_of(y.begin(), y.end(), [](double v) { return v == 0.0; })) << "factor " << factor;
    // And a matrix assembled on that storage factors as on fresh storage, bit for bit.
    BandedLU fresh;
    fillRandom(fresh, n, kl, ku, 4);
    fillRandom(lu, n, kl, ku, 4);
    ASSERT_TRUE(fresh.factor());
    ASSERT_TRUE(lu.factor());
    std::vector<double> a = ones(n), b = ones(n);
    fresh.solve(a);
    lu.solve(b);
    EXPECT_TRUE(a == b) << "factor " << factor;
  }
}

// Reset after set_reach zeroes the reach alone; the next matrix, of another pattern or shape, is
// the same as on fresh storage.
TEST(BandedLU, ResetWithinTheReachLeavesAZeroMatrix) {
  struct Shape {
    int n, kl, ku;
  };
  for (const Shape next : {Shape{60, 10, 10}, Shape{60, 14, 6}, Shape{45, 12, 12}, Shape{80, 9, 10}}) {
    BandedLU lu, fresh;
    std::vector<int> first, last, first2, last2;
    fillRagged(lu, 60, 10, 10, 1, first, last);
    lu.setReach(first, last);
    fillRagged(lu, next.n, next.kl, next.ku, 2, first2, last2);
    fillRagged(fresh, next.n, next.kl, next.ku, 2, first2, last2);
    std::mt19937_64 rng(6);
    std::vector<double> x(next.n), got, want;
    for (double& v : x) v = uniform(rng, -1, 1);
    lu.multiply(x, got);
    fresh.multiply(x, want);
    EXPECT_TRUE(got == want) << next.n << " " << next.kl << " " << next.ku;
  }
}

TEST(BandedLU, AReachOutsideTheBandIsRefused) {
  BandedLU lu;
  lu.reset(10, 2, 3);
  std::vector<int> first(10), last(10);
  for (int j = 0; j < 10; ++j) first[j] = last[j] = j;
  first[6] = 2;  // 4 above the diagonal, ku = 3
  EXPECT_THROW(lu.setReach(first, last), std::invalid_argument);
  first[6] = 3;
  last[0] = 3;  // 3 below, kl = 2
  EXPECT_THROW(lu.setReach(first, last), std::invalid_argument);
  EXPECT_THROW(lu.setReach(std::vector<int>(9), std::vector<int>(9)), std::invalid_argument);
}

}  // namespace
}  // namespace creaturelab::ib
