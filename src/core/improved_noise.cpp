#include "core/improved_noise.hpp"

#include <cmath>

#include "core/rng.hpp"

namespace creaturelab::core {
namespace {

// Perlin's permutation (the reference implementation's table).
constexpr std::array<std::uint8_t, 256> kReferencePermutation = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,  69,  142,
    8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,  197, 62,  94,  252, 219, 203,
    117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165,
    71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,
    55,  46,  245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,
    18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250,
    124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,  182, 189,
    28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,
    129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
    242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,
    181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114,
    67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};

constexpr double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
constexpr double lerp(double t, double a, double b) { return a + t * (b - a); }

// The dot product of (x, y, z) with one of the 12 cube-edge gradients picked by the hash.
constexpr double grad(int hash, double x, double y, double z) {
  const int h = hash & 15;
  const double u = h < 8 ? x : y;
  const double v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
  return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

bool isPeriod(int p) { return p >= 1 && p <= 256 && (p & (p - 1)) == 0; }

}  // namespace

ImprovedNoise ImprovedNoise::reference() { return ImprovedNoise(kReferencePermutation); }

ImprovedNoise ImprovedNoise::seeded(std::uint64_t seed) {
  std::array<std::uint8_t, 256> perm{};
  for (int i = 0; i < 256; ++i) perm[i] = std::uint8_t(i);
  Stream draws(seed, purposeId("core.improved_noise.permutation"));
  for (int i = 255; i > 0; --i) {
    const int j = int(draws.nextU64() % std::uint64_t(i + 1));  // bias below 1e-16: irrelevant here
    std::swap(perm[i], perm[j]);
  }
  return ImprovedNoise(perm);
}

bool ImprovedNoise::setPeriods(int px, int py, int pz) {
  if (!isPeriod(px) || !isPeriod(py) || !isPeriod(pz)) return false;
  mask_x_ = px - 1;
  mask_y_ = py - 1;
  mask_z_ = pz - 1;
  return true;
}

double ImprovedNoise::operator()(double x, double y, double z) const {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int X0 = int(fx) & mask_x_, Y0 = int(fy) & mask_y_, Z0 = int(fz) & mask_z_;
  const int X1 = (X0 + 1) & mask_x_, Y1 = (Y0 + 1) & mask_y_, Z1 = (Z0 + 1) & mask_z_;
  x -= fx;
  y -= fy;
  z -= fz;
  const double u = fade(x), v = fade(y), w = fade(z);
  const auto& p = perm_;
  const auto hash = [&p](int X, int Y, int Z) { return int(p[(p[(p[X] + Y) & 255] + Z) & 255]); };
  return lerp(w,
              lerp(v, lerp(u, grad(hash(X0, Y0, Z0), x, y, z), grad(hash(X1, Y0, Z0), x - 1, y, z)),
                   lerp(u, grad(hash(X0, Y1, Z0), x, y - 1, z), grad(hash(X1, Y1, Z0), x - 1, y - 1, z))),
              lerp(v, lerp(u, grad(hash(X0, Y0, Z1), x, y, z - 1), grad(hash(X1, Y0, Z1), x - 1, y, z - 1)),
                   lerp(u, grad(hash(X0, Y1, Z1), x, y - 1, z - 1), grad(hash(X1, Y1, Z1), x - 1, y - 1, z - 1))));
}

}  // namespace creaturelab::core
