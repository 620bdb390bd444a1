// The banded LU of the semi-implicit coupling (ib/banded_lu.hpp) against Eigen's dense partial-pivot
// LU: random banded systems whose small diagonal forces row interchanges, narrow and wide bands,
// the edges (n = 1, a band wider than the matrix), and a singular matrix reported as such.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "ib/banded_lu.hpp"

namespace creaturelab::ib {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
}

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
    const Eigen::VectorXd want = a.partialPivLu().solve(bv);
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
    const Eigen::VectorXd want = a.partialPivLu().solve(bv);
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

}  // namespace
}  // namespace creaturelab::ib
