#include "ib/kernel.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace creaturelab::ib {

std::string_view to_string(Kernel kernel) {
  switch (kernel) {
    case Kernel::bilinear:
      return "bilinear";
    case Kernel::peskin4:
      return "peskin4";
  }
  return "unknown";
}

std::optional<Kernel> parseKernel(std::string_view name) {
  for (Kernel kernel : {Kernel::bilinear, Kernel::peskin4}) {
    if (to_string(kernel) == name) return kernel;
  }
  return std::nullopt;
}

int kernelSupportCells(Kernel kernel) {
  switch (kernel) {
    case Kernel::bilinear:
      return 2;
    case Kernel::peskin4:
      return 4;
  }
  return kMaxKernelSupportCells;
}

// Peskin's square roots, sqrt(1 + 4|r| − 4r²) on [0, 1] and sqrt(−7 + 12|r| − 4r²) on [1, 2],
// are both sqrt(1 + 4u(1 − u)) with u = |r| on the first interval and u = |r| − 1 on the
// second (−7 + 12r − 4r² = 1 + 4(r − 1)(2 − r)). Written this way the radicand is 1 + a
// product of two small non-negative numbers, without the cancellation of the expanded
// quadratic near the ends of each interval, and lies in [1, 2].
namespace {
double peskinRoot(double u) { return std::sqrt(1.0 + 4.0 * u * (1.0 - u)); }
}  // namespace

double kernelWeight_1d(Kernel kernel, double r_cells) {
  const double r = std::abs(r_cells);
  if (std::isnan(r)) return std::numeric_limits<double>::quiet_NaN();
  switch (kernel) {
    case Kernel::bilinear:
      // Rudolf & Mould 2009 §3.2: the hat function of bilinear interpolation.
      return r < 1.0 ? 1.0 - r : 0.0;
    case Kernel::peskin4:
      // Peskin 2002 §6, the 4-point function (see kernel.hpp for the formula as printed).
      if (r <= 1.0) return (3.0 - 2.0 * r + peskinRoot(r)) / 8.0;
      if (r < 2.0) {
        const double u = r - 1.0;  // 5 − 2r = 3 − 2u
        return (3.0 - 2.0 * u - peskinRoot(u)) / 8.0;
      }
      return 0.0;
  }
  return 0.0;
}

void kernelWeights_1d(Kernel kernel, double t, double (&weights)[kMaxKernelSupportCells]) {
  switch (kernel) {
    case Kernel::bilinear:
      // Faces f and f + 1 at distances t and 1 − t.
      weights[0] = 1.0 - t;
      weights[1] = t;
      weights[2] = 0.0;
      weights[3] = 0.0;
      return;
    case Kernel::peskin4: {
      // Faces f − 1, f, f + 1, f + 2 at distances 1 + t, t, 1 − t, 2 − t. With q = sqrt(1 + 4t − 4t²)
      // Peskin's two branches become (substitute |r| = 1 + t, t, 1 − t, 2 − t):
      //   phi(1 + t) = (3 − 2t − q)/8,  phi(t) = (3 − 2t + q)/8,
      //   phi(1 − t) = (1 + 2t + q)/8,  phi(2 − t) = (1 + 2t − q)/8,
      // one square root for all four; the q cancel in the even pair (f − 1, f + 1) and in the odd
      // pair (f, f + 2), each summing to 4/8 = 1/2 (Peskin's even/odd condition).
      const double q = peskinRoot(t);
      const double a = 3.0 - 2.0 * t;
      const double b = 1.0 + 2.0 * t;
      weights[0] = (a - q) / 8.0;
      weights[1] = (a + q) / 8.0;
      weights[2] = (b + q) / 8.0;
      weights[3] = (b - q) / 8.0;
      return;
    }
  }
}

int stencilFaces(Kernel kernel, int scale) {
  const int faces = scale * kernelSupportCells(kernel);
  if (scale < 1 || faces > kMaxStencilFaces) {
    throw std::invalid_argument("immersed-boundary kernel: a " + std::string(to_string(kernel)) +
                                " kernel stretched " + std::to_string(scale) + " times is not supported (the scale must be " +
                                "a whole number from 1 to " + std::to_string(kMaxStencilFaces / kernelSupportCells(kernel)) +
                                ")");
  }
  return faces;
}

void stretchedKernelWeights_1d(Kernel kernel, int scale, double t, double (&weights)[kMaxStencilFaces]) {
  const int faces = stencilFaces(kernel, scale);
  if (scale == 1) {
    double base[kMaxKernelSupportCells];
    kernelWeights_1d(kernel, t, base);
    for (int a = 0; a < kMaxStencilFaces; ++a) weights[a] = a < kMaxKernelSupportCells ? base[a] : 0.0;
    return;
  }
  const double inv_scale = 1.0 / scale;
  const double first = t + 0.5 * faces - 1.0;  // distance, in cells, from the point to the stencil's first face
  for (int a = 0; a < kMaxStencilFaces; ++a)
    weights[a] = a < faces ? kernelWeight_1d(kernel, (first - a) * inv_scale) * inv_scale : 0.0;
}

}  // namespace creaturelab::ib
