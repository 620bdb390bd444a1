// The 1-D immersed-boundary kernels (ib/kernel.hpp) against their formulas and the discrete
// conditions Peskin 2002 (Acta Numerica 11, §6) builds the 4-point function from, at many
// seeded random offsets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "ib/kernel.hpp"
#include "test_random.hpp"

namespace creaturelab::ib {
namespace {

using test::uniform01;

constexpr int kSamples = 20000;

// The formula exactly as printed in Peskin 2002 §6, independent of the library's rewriting.
double peskin4_as_printed(double r) {
  const double a = std::abs(r);
  if (a <= 1.0) return (3.0 - 2.0 * a + std::sqrt(1.0 + 4.0 * a - 4.0 * r * r)) / 8.0;
  if (a <= 2.0) return (5.0 - 2.0 * a - std::sqrt(-7.0 + 12.0 * a - 4.0 * r * r)) / 8.0;
  return 0.0;
}

class KernelTest : public ::testing::TestWithParam<Kernel> {};

TEST(KernelNames, RoundTripAndRejectUnknownNames) {
  EXPECT_EQ(to_string(Kernel::bilinear), "bilinear");
  EXPECT_EQ(to_string(Kernel::peskin4), "peskin4");
  for (Kernel k : {Kernel::bilinear, Kernel::peskin4}) EXPECT_EQ(parseKernel(to_string(k)), k);
  EXPECT_FALSE(parseKernel("Bilinear"));
  EXPECT_FALSE(parseKernel("peskin"));
  EXPECT_FALSE(parseKernel(""));
  EXPECT_EQ(kernelSupportCells(Kernel::bilinear), 2);
  EXPECT_EQ(kernelSupportCells(Kernel::peskin4), 4);
}

TEST(KernelFormula, BilinearIsTheHatFunction) {
  std::mt19937_64 rng(11);
  for (int n = 0; n < kSamples; ++n) {
    const double r = -3.0 + 6.0 * uniform01(rng);
    EXPECT_EQ(kernelWeight_1d(Kernel::bilinear, r), std::max(0.0, 1.0 - std::abs(r))) << "r = " << r;
  }
  EXPECT_EQ(kernelWeight_1d(Kernel::bilinear, 0.0), 1.0);
  EXPECT_EQ(kernelWeight_1d(Kernel::bilinear, 0.25), 0.75);
  EXPECT_EQ(kernelWeight_1d(Kernel::bilinear, -1.0), 0.0);
}

TEST(KernelFormula, Peskin4MatchesThePrintedFormula) {
  std::mt19937_64 rng(12);
  for (int n = 0; n < kSamples; ++n) {
    const double r = -3.0 + 6.0 * uniform01(rng);
    EXPECT_NEAR(kernelWeight_1d(Kernel::peskin4, r), peskin4_as_printed(r), 1e-15) << "r = " << r;
  }
  // Values from the formula by hand: phi(0) = 1/2, phi(1/2) = (2 + sqrt 2)/8, phi(1) = 1/4,
  // phi(3/2) = (2 − sqrt 2)/8, phi(2) = 0.
  EXPECT_DOUBLE_EQ(kernelWeight_1d(Kernel::peskin4, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(kernelWeight_1d(Kernel::peskin4, 0.5), (2.0 + std::sqrt(2.0)) / 8.0);
  EXPECT_DOUBLE_EQ(kernelWeight_1d(Kernel::peskin4, -1.0), 0.25);
  EXPECT_DOUBLE_EQ(kernelWeight_1d(Kernel::peskin4, 1.5), (2.0 - std::sqrt(2.0)) / 8.0);
  EXPECT_EQ(kernelWeight_1d(Kernel::peskin4, 2.0), 0.0);
  // Continuous where the branches meet.
  EXPECT_NEAR(kernelWeight_1d(Kernel::peskin4, std::nextafter(1.0, 0.0)),
              kernelWeight_1d(Kernel::peskin4, std::nextafter(1.0, 2.0)), 1e-15);
}

TEST_P(KernelTest, IsSymmetricNonNegativeAndZeroOutsideItsSupport) {
  const Kernel kernel = GetParam();
  const double half_width = 0.5 * kernelSupportCells(kernel);
  std::mt19937_64 rng(13);
  for (int n = 0; n < kSamples; ++n) {
    const double r = -4.0 + 8.0 * uniform01(rng);
    const double phi = kernelWeight_1d(kernel, r);
    EXPECT_EQ(phi, kernelWeight_1d(kernel, -r));
    EXPECT_GE(phi, 0.0);
    if (std::abs(r) >= half_width) {
      EXPECT_EQ(phi, 0.0) << "r = " << r;
    }
  }
  EXPECT_TRUE(std::isnan(kernelWeight_1d(kernel, std::numeric_limits<double>::quiet_NaN())));
  EXPECT_EQ(kernelWeight_1d(kernel, std::numeric_limits<double>::infinity()), 0.0);
}

// Σ_j phi(r − j) = 1 and Σ_j (r − j) phi(r − j) = 0 for every r: the partition of unity and
// the zero first moment that make spreading conserve force and interpolation exact on linear
// fields. Peskin4 also: Σ_even = Σ_odd = 1/2 and Σ_j phi(r − j)² = 3/8.
TEST_P(KernelTest, OneDimensionalMomentConditions) {
  const Kernel kernel = GetParam();
  std::mt19937_64 rng(14);
  for (int n = 0; n < kSamples; ++n) {
    const double r = -5.0 + 10.0 * uniform01(rng);
    double sum = 0.0, first = 0.0, squares = 0.0, even = 0.0, odd = 0.0;
    for (int j = -8; j <= 8; ++j) {
      const double phi = kernelWeight_1d(kernel, r - j);
      sum += phi;
      first += (r - j) * phi;
      squares += phi * phi;
      (j % 2 == 0 ? even : odd) += phi;
    }
    EXPECT_NEAR(sum, 1.0, 1e-15) << "r = " << r;
    EXPECT_NEAR(first, 0.0, 1e-14) << "r = " << r;
    if (kernel == Kernel::peskin4) {
      EXPECT_NEAR(squares, 3.0 / 8.0, 1e-15) << "r = " << r;
      EXPECT_NEAR(even, 0.5, 1e-15) << "r = " << r;
      EXPECT_NEAR(odd, 0.5, 1e-15) << "r = " << r;
    }
  }
}

// The whole-stencil weights (used by the transfer) equal the kernel at each face and keep the
// conditions above.
TEST_P(KernelTest, StencilWeightsEqualTheKernelAndSumToOne) {
  const Kernel kernel = GetParam();
  const int s = kernelSupportCells(kernel);
  std::mt19937_64 rng(15);
  for (int n = 0; n < kSamples; ++n) {
    const double t = n == 0 ? 0.0 : uniform01(rng);
    double w[kMaxKernelSupportCells] = {-1.0, -1.0, -1.0, -1.0};
    kernelWeights_1d(kernel, t, w);
    double sum = 0.0, first = 0.0, even = 0.0, odd = 0.0;
    for (int a = 0; a < kMaxKernelSupportCells; ++a) {
      const double r = t + s / 2 - 1 - a;  // distance of the point from face a of its stencil
      if (a < s) {
        EXPECT_NEAR(w[a], kernelWeight_1d(kernel, r), 1e-15) << "t = " << t << ", a = " << a;
        EXPECT_GE(w[a], 0.0);
      } else {
        EXPECT_EQ(w[a], 0.0);
      }
      sum += w[a];
      first += r * w[a];
      (a % 2 == 0 ? even : odd) += w[a];
    }
    EXPECT_NEAR(sum, 1.0, 5e-16) << "t = " << t;  // a few roundings
    EXPECT_NEAR(first, 0.0, 1e-15) << "t = " << t;
    if (kernel == Kernel::peskin4) {
      EXPECT_NEAR(even, 0.5, 2e-16) << "t = " << t;
      EXPECT_NEAR(odd, 0.5, 2e-16) << "t = " << t;
    }
  }
}

// A kernel stretched m times (a fixed physical width on a finer grid): its stencil weights are
// phi(r / m) / m at each face and keep the partition of unity and zero first moment for every
// whole m; m = 1 is the grid kernel bit for bit.
TEST_P(KernelTest, StretchedStencilKeepsTheMomentConditions) {
  const Kernel kernel = GetParam();
  std::mt19937_64 rng(16);
  const int largest = kMaxStencilFaces / kernelSupportCells(kernel);
  for (int m = 1; m <= largest; ++m) {
    const int faces = stencilFaces(kernel, m);
    ASSERT_EQ(faces, m * kernelSupportCells(kernel));
    for (int n = 0; n < 2000; ++n) {
      const double t = n == 0 ? 0.0 : uniform01(rng);
      double w[kMaxStencilFaces];
      stretchedKernelWeights_1d(kernel, m, t, w);
      double sum = 0.0, first = 0.0;
      for (int a = 0; a < kMaxStencilFaces; ++a) {
        const double r = t + faces / 2 - 1 - a;
        if (a < faces) {
          EXPECT_NEAR(w[a], kernelWeight_1d(kernel, r / m) / m, 1e-15) << "m = " << m << ", t = " << t;
        } else {
          EXPECT_EQ(w[a], 0.0);
        }
        sum += w[a];
        first += r * w[a];
      }
      EXPECT_NEAR(sum, 1.0, 1e-14) << "m = " << m << ", t = " << t;
      EXPECT_NEAR(first, 0.0, 1e-13) << "m = " << m << ", t = " << t;
      if (m == 1) {
        double base[kMaxKernelSupportCells];
        kernelWeights_1d(kernel, t, base);
        for (int a = 0; a < kernelSupportCells(kernel); ++a) EXPECT_EQ(w[a], base[a]);
      }
    }
  }
  EXPECT_THROW(stencilFaces(kernel, 0), std::invalid_argument);
  EXPECT_THROW(stencilFaces(kernel, largest + 1), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Kernels, KernelTest, ::testing::Values(Kernel::bilinear, Kernel::peskin4),
                         [](const ::testing::TestParamInfo<Kernel>& tested) { return std::string(to_string(tested.param)); });

}  // namespace
}  // namespace creaturelab::ib
