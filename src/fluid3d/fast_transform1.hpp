#pragma once
// Fast 1-D transforms onto the orthonormal eigenbases of spectral_pressure_solver3.hpp, for lines
// whose length n is a power of two: the periodic basis by a complex FFT of the real line, the
// solid–solid (DCT-II) basis by Makhoul's reordering into one complex FFT of length n (Makhoul 1980,
// "A fast cosine transform in one and multiple dimensions", IEEE Trans. ASSP 28, §II). Radix-2
// Cooley–Tukey, iterative. The coefficients are those of the dense basis (same order, same signs),
// to round-off. (The 2-D solver's FFT, fluid/fast_pressure_solver2.cpp, is private to that file.)

#include <vector>

#include "fluid3d/fluid_params3.hpp"

namespace creaturelab::fluid3d {

class FastTransform1 {
 public:
  /// Whether a line of n samples between these sides has a fast transform.
  static bool applies(int n, const AxisBoundary3& sides);
  /// Precomputes the tables; requires applies(n, sides).
  FastTransform1(int n, const AxisBoundary3& sides);

  /// coefficients[m] = Σ_j φ_m(j) line[j]; `work` is scratch of 4 n doubles.
  void forward(const double* line, double* coefficients, double* work) const;
  /// line[j] = Σ_m φ_m(j) coefficients[m].
  void inverse(const double* coefficients, double* line, double* work) const;
  int size() const { return n_; }

 private:
  void fft(double* re, double* im, bool inverse) const;  // unnormalised, sign −/+ for forward/inverse

  int n_ = 0;
  bool periodic_ = false;
  std::vector<int> bit_reverse_;
  std::vector<double> cos_, sin_;              // cos, sin(2π t / n), t < n/2
  std::vector<double> shift_cos_, shift_sin_;  // cos, sin(π k / 2n), k < n
};

}  // namespace creaturelab::fluid3d
