#pragma once
// Fast direct pressure solver for the uniform box (Schumann & Sweet 1988, "Fast Fourier
// transforms for direct solution of Poisson's equation with staggered boundary conditions",
// J. Comput. Phys. 75; Makhoul 1980 for the cosine transform by FFT).
//
// The matrix A of pressure_solver2.hpp is a Kronecker sum A = T_x ⊗ I + I ⊗ T_y of 1-D
// operators tridiag(−1, 2, −1) whose end entries are 1 at a solid wall (Neumann) and 3 at an
// open wall (p = 0 on the wall). Each 1-D operator has sinusoidal eigenvectors:
//   Neumann–Neumann     φ_k(j) = cos(π k (j+½)/n),        λ_k = 4 sin²(π k / 2n)       (DCT-II)
//   Dirichlet–Dirichlet φ_k(j) = sin(π (k+1)(j+½)/n),     λ_k = 4 sin²(π (k+1) / 2n)   (DST-II)
//   Neumann–Dirichlet   φ_k(j) = cos(π (k+½)(j+½)/n),     λ_k = 4 sin²(π (k+½) / 2n)   (DCT-IV)
//   Dirichlet–Neumann   φ_k(j) = sin(π (k+½)(j+½)/n),     λ_k as above                 (DST-IV)
// We transform along one axis ("lines"), which turns A into one tridiagonal system
// (T_other + λ_k I) per mode k along the other axis ("lanes"), solved by the Thomas algorithm
// (pivots precomputed), and transform back. Cost: O(N log n) with the FFT (Neumann–Neumann
// lines whose length n is even with n/2 a product of 2, 3, 5 and 7, e.g. the paper's free-slip
// box of 100 or 50 cells), O(N n) with a dense transform otherwise. Exact to round-off; in a
// closed box the one singular mode (k = 0, constant) is solved with mean zero. All loops run in a fixed order: results
// are bitwise reproducible.
//
// The same machinery solves the shifted system (σ I + T_x ⊗ I + I ⊗ T_y) q = b, σ ≥ 0, whose
// eigenvectors are those of σ = 0 and whose lane systems are (T_lane + (λ_k + σ) I): the
// implicit viscosity step (I − α ∇²) u = b is σ = 1/α on b/α (fast_diffusion2.hpp). Its lanes
// may also end on a known zero one cell beyond (a solid wall's normal face): end entry 2.

#include <vector>

#include "fluid/pressure_solver2.hpp"

namespace creaturelab::fluid {

/// An end of a 1-D operator tridiag(−1, 2, −1): its first or last diagonal entry.
enum class OperatorEnd {
  neumann,         ///< 1: no flux through the end (pressure at a solid wall)
  dirichlet_half,  ///< 3: zero half a cell beyond (pressure at an open wall, p = 0 on it)
  dirichlet_node   ///< 2: zero one cell beyond (lanes only: not a transform's line)
};

/// σ I + T_x ⊗ I + I ⊗ T_y on an nx × ny array, with the ends of T_x and T_y.
struct KroneckerOperator2 {
  OperatorEnd x_low = OperatorEnd::neumann, x_high = OperatorEnd::neumann;
  OperatorEnd y_low = OperatorEnd::neumann, y_high = OperatorEnd::neumann;
  double shift = 0.0;  ///< σ ≥ 0
  bool operator==(const KroneckerOperator2&) const = default;
};

/// The pressure operator of pressure_solver2.hpp: Neumann at solid walls, Dirichlet half a
/// cell beyond open ones, σ = 0.
KroneckerOperator2 pressureOperator(const Walls& walls);

class FastPressureSolver2 final : public PressureSolver2 {
 public:
  enum class Method {
    fft_along_y,   ///< DCT-II by a mixed-radix FFT along y, Thomas along x
    fft_along_x,   ///< the same on the transposed problem
    dense_along_y,  ///< dense orthonormal eigenbasis along y (any wall types, any size)
    dense_along_x   ///< the same on the transposed problem (when y has a dirichlet_node end)
  };

  LinearSolveReport project(MacGrid2& grid, const Walls& walls, double density_kg_per_m3, double dt_s) override;

  /// Solves A q = output_scale · b to round-off. In a closed box the mean of b is ignored (removed)
  /// and q has mean zero (to round-off).
  /// `prefer_dense` forces the dense path (tests compare the two).
  void solve(const Walls& walls, const Array2& b, Array2& q, bool prefer_dense = false, double output_scale = 1.0);
  /// Solves op q = output_scale · b to round-off (the same, for any operator; singular only when
  /// all ends are Neumann and σ = 0). Throws std::invalid_argument when both axes have a
  /// dirichlet_node end (no transform along either).
  void solve(const KroneckerOperator2& op, const Array2& b, Array2& q, bool prefer_dense = false,
             double output_scale = 1.0);

  /// The method chosen by the last solve.
  Method method() const { return method_; }

 private:
  void setup(const KroneckerOperator2& op, int nx, int ny, bool prefer_dense);
  // The pieces of a solve; [l0, l1) a range of lanes, [k0, k1) of modes (threads share them).
  // One FFT scratch per thread: its piece of the lanes in arrays of the piece's own width, so
  // that the FFT's stages of two threads never write into the same rows. (Shared rows cut at a
  // cache line were rejected: two threads were then no faster than one, since the halves of a row
  // are neighbours in memory, which the cores then trade.)
  struct FftPanel {
    Array2 re, im, re2, im2;
  };
  void forwardTransform(const Array2& source, double scale, int l0, int l1, FftPanel& panel);
  void inverseTransform(Array2& target, int l0, int l1, FftPanel& panel);
  void fft(bool inverse, FftPanel& panel);
  bool resultInSecondBuffers() const { return fftPasses(radices_) % 2 == 1; }
  static int fftPasses(const std::vector<int>& radices);
  void solveModes(int k0, int k1);

  bool ready_ = false;
  bool prefer_dense_ = false;
  KroneckerOperator2 op_{};
  int nx_ = 0, ny_ = 0;
  Method method_ = Method::fft_along_y;
  bool transposed_ = false;  // lines along x
  bool dense_ = false;       // dense eigenbasis instead of the FFT
  int lines_ = 0;  // transform length n
  int lanes_ = 0;  // tridiagonal length m
  bool singular_ = false;
  Array2 pivots_;                                  // lanes × lines: row k holds mode k's 1/pivots
  std::vector<int> radices_;                       // FFT of length n/2: stage radices
  std::vector<double> fft_cos_, fft_sin_;          // cos, sin(2π t / (n/2)), t < n/2
  std::vector<double> twiddle_cos_, twiddle_sin_;  // cos, sin(2π t / n), t < n/2
  std::vector<double> shift_cos_, shift_sin_;      // cos, sin(π k / 2n), k < n
  Array2 basis_;                                   // dense: basis_(j, k) = φ_k(j), contiguous in j
  Array2 basis_t_;                                 // dense: basis_t_(k, j) = φ_k(j), contiguous in k
  Array2 work_, dense_out_, rhs_;
  std::vector<FftPanel> panels_;  // one per thread
  std::vector<MaxAbsAccumulator> accumulators_;  // one per thread
};

}  // namespace creaturelab::fluid
