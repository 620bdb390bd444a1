#pragma once
// One-dimensional kernels phi of the immersed-boundary (IB) method. The discrete delta
// function of the 2-D method is their tensor product (Peskin 2002, Acta Numerica 11, §6):
//
//     delta_h(x, y) = phi(x / dx) phi(y / dx) / dx^2,
//
// so a marker force is spread onto, and the fluid velocity is interpolated from, the
// support x support faces nearest to the marker (see transfer.hpp).
//
// Two kernels:
//  - bilinear: phi(r) = max(0, 1 − |r|). The "four closest grid cells with bilinear
//    interpolation" of Rudolf & Mould 2009 (§3.2),
//    chosen there over Peskin's kernel because a wider kernel makes a coarse (50² or 100²)
//    grid look artificially viscous.
//  - peskin4: Peskin's 4-point function (Peskin 2002, §6: the one built from his postulates
//    without cosines),
//        phi(r) = (3 − 2|r| + sqrt(1 + 4|r| − 4r²)) / 8    for 0 ≤ |r| ≤ 1,
//                 (5 − 2|r| − sqrt(−7 + 12|r| − 4r²)) / 8   for 1 ≤ |r| ≤ 2,
//                 0                                         for 2 ≤ |r|.
//    For every real r it satisfies (ibid.) Σ_j phi(r − j) = 1, Σ_j (r − j) phi(r − j) = 0,
//    Σ_{j even} phi(r − j) = Σ_{j odd} phi(r − j) = 1/2 (no checkerboard), and
//    Σ_j phi(r − j)² = 3/8 (approximate translation invariance of the spread-interpolate pair).
//    The bilinear kernel shares the first two (partition of unity, zero first moment), which
//    is what makes interpolation of a linear field exact; it has neither of the last two.

#include <optional>
#include <string_view>

namespace creaturelab::ib {

enum class Kernel {
  bilinear,  ///< 2-point hat, phi(r) = max(0, 1 − |r|) (Rudolf & Mould 2009, §3.2)
  peskin4    ///< Peskin's 4-point function (Peskin 2002, §6)
};

/// "bilinear" or "peskin4" (the enumerator names).
std::string_view to_string(Kernel kernel);
/// Inverse of to_string (exact, case-sensitive match); std::nullopt for an unknown name.
std::optional<Kernel> parseKernel(std::string_view name);

/// Width of the kernel's support in cells: phi(r) = 0 for |r| ≥ support / 2. Also the number of
/// faces per axis a marker's stencil covers: 2 (bilinear) or 4 (peskin4).
int kernelSupportCells(Kernel kernel);

/// The largest kernelSupportCells() of any kernel.
inline constexpr int kMaxKernelSupportCells = 4;

/// The largest stencil width, in faces per axis, of a stretched kernel (stretched_kernel_weights_1d):
/// scale × support ≤ 24, e.g. bilinear up to scale 12 or peskin4 up to scale 6 (fixed-size storage): a
/// 4 mm peskin4 radius down to 1/3 mm cells.
inline constexpr int kMaxStencilFaces = 24;

/// phi(r) with r = distance / dx in cells (dimensionless; symmetric in r). NaN for a NaN r.
double kernelWeight_1d(Kernel kernel, double r_cells);

/// The weights of a whole stencil. A point at xs (in face-index units) has the stencil
/// faces f − s/2 + 1 + a, a = 0..s−1, with f = floor(xs), t = xs − f in [0, 1) and
/// s = kernelSupportCells(kernel); weights[a] = phi(t + s/2 − 1 − a), unused entries 0.
/// Equal to s calls of kernel_weight_1d to round-off, but with one square root (peskin4) and
/// written so that the weights sum to 1 (and, for peskin4, the even and odd ones to 1/2) up
/// to a few roundings.
void kernelWeights_1d(Kernel kernel, double t, double (&weights)[kMaxKernelSupportCells]);

/// The kernel stretched by a whole factor m ≥ 1, phi_m(r) = phi(r / m) / m, whose support is
/// m · support faces: a delta function of fixed physical width on any grid whose cell divides
/// it (Peskin 2002 §6 scales the same phi by dx; here the width is m dx, so refining the grid
/// at fixed width m dx converges to one regularised problem instead of a thinner one each time).
/// Its faces, in units of r / m, fall into m interleaved sets of unit spacing, each of which has
/// phi's partition of unity and zero first moment, so phi_m keeps both exactly for whole m.
/// The stencil of a point at xs starts at face floor(xs) − m·s/2 + 1 and
/// weights[a] = phi_m(t + m·s/2 − 1 − a), a = 0..m·s−1; for m = 1 these are kernel_weights_1d's
/// weights, bit for bit. Throws std::invalid_argument if m < 1 or m · support > kMaxStencilFaces.
void stretchedKernelWeights_1d(Kernel kernel, int scale, double t, double (&weights)[kMaxStencilFaces]);

/// Faces per axis of the stretched kernel's stencil: scale · kernelSupportCells(kernel).
int stencilFaces(Kernel kernel, int scale);

}  // namespace creaturelab::ib
