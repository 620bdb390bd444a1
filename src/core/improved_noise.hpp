#pragma once
// Perlin's improved noise (K. Perlin, "Improving Noise", SIGGRAPH 2002; his Java reference
// implementation, cs.nyu.edu/~perlin/noise/), the Q_P of Rudolf & Mould 2009 Eq. 2
// (Rudolf & Mould 2009 §3.5): a C² scalar field over 3-D space, zero at every
// integer lattice point, with values in about [-1, 1].
//
// Written here rather than taken from Debian's libnoise because the jellyfish needs two things
// libnoise does not give: (1) a lattice that is periodic in a chosen coordinate, so that noise
// sampled at (2 d_i, 8 d_j, 0.01 t) with the longitude d_j in [0, 1) closes seamlessly around the
// bell (period 8 in y); (2) the 2002 algorithm itself (libnoise's Perlin module is its own
// gradient noise, with other gradients and hashing), checked against Perlin's reference output.
//
// Lattice hash, for corner (X, Y, Z) wrapped to the periods (px, py, pz), each dividing 256:
//   h = perm[(perm[(perm[X] + Y) mod 256] + Z) mod 256]
// which with periods 256 is exactly the reference's p[p[p[X] + Y] + Z] on its doubled table.
// gradient(h) is the reference's 12 cube-edge directions (h & 15, four repeated), and the
// interpolant is the quintic fade 6t⁵ − 15t⁴ + 10t³.
#include <array>
#include <cstdint>

namespace creaturelab::core {

class ImprovedNoise {
 public:
  /// Perlin's reference permutation: noise(3.14, 42, 7) = 0.13691995878400012 (the value the
  /// reference Java code prints; Rosetta Code's "Perlin noise" task).
  static ImprovedNoise reference();
  /// A permutation shuffled (Fisher-Yates) by the counter-based generator keyed by `seed`
  /// (core/rng.hpp): the same seed gives the same field on every machine and build.
  static ImprovedNoise seeded(std::uint64_t seed);

  /// Makes the lattice periodic: noise(x + px, y, z) = noise(x, y, z), and likewise in y and z.
  /// Each period must divide 256 (1, 2, 4, ..., 256); 256 is the reference's own period.
  /// Returns false (and changes nothing) for another value.
  bool setPeriods(int px, int py, int pz);

  double operator()(double x, double y, double z) const;

 private:
  explicit ImprovedNoise(const std::array<std::uint8_t, 256>& permutation) : perm_(permutation) {}

  std::array<std::uint8_t, 256> perm_;
  int mask_x_ = 255, mask_y_ = 255, mask_z_ = 255;  // period - 1
};

}  // namespace creaturelab::core
