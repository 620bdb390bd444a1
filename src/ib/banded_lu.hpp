#pragma once
// LU factorisation with partial pivoting of a banded matrix (Golub & Van Loan, Matrix Computations,
// 4th ed., §4.3.5; the storage and the pivoting of LAPACK's dgbtf2/dgbtrs).
//
// Why: the semi-implicit coupling solves (I − dt M K) U = r every step (ib/coupling.hpp), n = 2 x
// markers unknowns; for a 256-segment bell (419 markers) the dense LU would dominate the step.
// Ordered so that markers near each other in space are near each other
// in the unknowns (ElasticBody::solveOrder), the system is banded: an entry couples two markers
// only through their shared faces (M, within the kernel's support) or a spring (K).
//
// Storage: n columns of 2 kl + ku + 1 rows, A(i, j) in row kl + ku + i − j of column j; the kl rows
// on top hold the fill of the row interchanges, so U has kl + ku superdiagonals. Deterministic:
// the same matrix gives the same factors bit for bit (no threads, a fixed order of operations).
//
// Reach: setReach() takes, from the code that assembled the matrix, the rows of each column that
// it may have made nonzero, for multiply() and for the next reset() to zero only those: a bell's
// band is mostly zero rows, which would otherwise be zeroed and multiplied every step. (Scanning the
// band for the reach instead was rejected: it cost about as much as it saved.)
#include <cstddef>
#include <vector>

namespace creaturelab::ib {

class BandedLU {
 public:
  /// Zeroes an n x n matrix with kl sub- and ku superdiagonals (keeps the storage). Of a matrix
  /// whose reach is known (set_reach), only the reach is zeroed.
  void reset(int n, int kl, int ku);
  int size() const { return n_; }
  int lower() const { return kl_; }
  int upper() const { return ku_; }
  /// A(i, j), which must lie in the band (|j − i| within ku above, kl below). Forgets the reach.
  double& at(int i, int j) {
    reach_known_ = false;
    return band_[static_cast<std::size_t>(j) * rows_ + (kl_ + ku_ + i - j)];
  }
  /// Column j of the band by row: column(j)[i] is at(i, j), for i in the band. Forgets the reach;
  /// the pointer is for writing before the next setReach().
  double* column(int j) {
    reach_known_ = false;
    return band_.data() + static_cast<std::ptrdiff_t>(j) * (rows_ - 1) + (kl_ + ku_);
  }
  /// Column j's nonzeros lie in rows first[j] .. last[j] (first[j] > last[j]: none); zero entries
  /// may lie there too. Given after the last write; the next write through at() or column(),
  /// factor() or reset() forgets it. Throws std::invalid_argument for rows outside the band.
  void setReach(const std::vector<int>& first, const std::vector<int>& last);
  /// Factors in place. False if a pivot is exactly zero (a singular matrix); the factors are then
  /// not usable.
  bool factor();
  /// Solves A x = b in place with the factors of factor().
  void solve(std::vector<double>& b) const;
  /// y = A x, for a matrix not yet factored (a fixed order of operations, like factor()); over each
  /// column's reach when it is known, with the same result for finite x.
  void multiply(const std::vector<double>& x, std::vector<double>& y) const;

 private:
  double& ab(int row, int j) { return band_[static_cast<std::size_t>(j) * rows_ + row]; }
  double ab(int row, int j) const { return band_[static_cast<std::size_t>(j) * rows_ + row]; }
  int n_ = 0, kl_ = 0, ku_ = 0, rows_ = 0;
  std::vector<double> band_;
  std::vector<int> pivot_;
  // Per column of the factors, the farthest nonzero below the diagonal in L and above it in U.
  std::vector<int> lower_rows_, upper_rows_;
  void findFactorExtents();
  // Per column of the matrix, the rows that may be nonzero (set_reach), valid while reach_known_.
  std::vector<int> first_row_, last_row_;
  bool reach_known_ = false;
  void zeroReach();
};

}  // namespace creaturelab::ib
