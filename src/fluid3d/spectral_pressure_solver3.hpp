#pragma once
// Exact pressure solve in the uniform box by eigen-decomposition (Schumann & Sweet 1988, the 3-D
// form of fluid/fast_pressure_solver2.hpp).
//
// A = T_x ⊗ I ⊗ I + I ⊗ T_y ⊗ I + I ⊗ I ⊗ T_z with 1-D operators tridiag(−1, 2, −1) whose ends
// are 1 at a solid wall, 3 at an open side, or wrap around (periodic). Their orthonormal
// eigenvectors, with θ the angle and λ = 4 sin²(θ/2):
//   periodic            1, cos(2π m j/n), sin(2π m j/n), (−1)^j       θ = 2π m / n
//   solid–solid         cos(π k (j+½)/n)                              θ = π k / n
//   open–open           sin(π (k+1)(j+½)/n)                           θ = π (k+1) / n
//   solid–open          cos(π (k+½)(j+½)/n)   (open–solid: sin)        θ = π (k+½) / n
// q = B (Λ⁻¹ (Bᵀ b)) with B the product of the three bases; the constant mode of a closed box is
// set to zero (mean zero). Along a periodic or solid–solid axis whose length is a power of two the
// 1-D transforms are FFTs (fast_transform1.hpp), O(N log n); otherwise dense, O(N n).
// Every loop runs in a fixed order: bitwise reproducible for any thread count.

#include <memory>

#include "fluid3d/fast_transform1.hpp"
#include "fluid3d/pressure_solver3.hpp"

namespace creaturelab::fluid3d {

/// The orthonormal eigenbasis of one 1-D operator: basis[j * n + m] = φ_m(j), eigenvalue[m].
struct EigenBasis1 {
  int n = 0;
  std::vector<double> basis, eigenvalue;
};
EigenBasis1 eigenBasis(int n, const AxisBoundary3& sides);

class SpectralPressureSolver3 final : public PressureSolver3 {
 public:
  /// allow_fast = false forces the dense transforms (tests compare the two).
  explicit SpectralPressureSolver3(bool allow_fast = true) : allow_fast_(allow_fast) {}
  /// Whether the last solve's transform along axis a was an FFT.
  bool fastAlong(int a) const { return fast_[a] != nullptr; }
  SolveReport3 solve(const std::array<int, 3>& cells, const Boundaries3& sides, const Array3& b, Array3& q) override;

 private:
  void prepare(const std::array<int, 3>& cells, const Boundaries3& sides);
  /// out = along axis a: out_m = Σ_j φ_m(j) in_j (forward) or out_j = Σ_m φ_m(j) in_m (inverse).
  void transform(int a, bool forward, const Array3& in, Array3& out);

  bool allow_fast_ = true;
  bool ready_ = false;
  std::array<std::unique_ptr<FastTransform1>, 3> fast_;
  std::array<int, 3> cells_{};
  Boundaries3 sides_{};
  std::array<EigenBasis1, 3> bases_;
  Array3 t1_, t2_;
};

}  // namespace creaturelab::fluid3d
