#pragma once
// Deterministic counter-based random numbers (DESIGN.md, Conventions: "Randomness comes
// from a seeded counter-based generator keyed by (seed, purpose, index)").
//
// Every draw is a pure function of (seed, purpose, index): no hidden state, so results
// cannot depend on thread count, rank count or the order in which sweep points run.
//
// Construction (SplitMix64, Steele, Lea & Flood 2014, "Fast splittable pseudorandom
// number generators"; finaliser "Mix13" by D. Stafford):
//   key(seed, purpose) = mix64(mix64(seed + G) ^ purpose)
//   hash64(seed, purpose, index) = mix64(key + (index + 1) * G),   G = 0x9e3779b97f4a7c15
// i.e. draw `index` of the SplitMix64 stream seeded with `key`, which passes BigCrush.
// For a fixed key, index -> hash64 is a bijection (mix64 is invertible and G is odd), so
// distinct indices never collide. Rejected alternative: Philox-4x32-10 (Salmon et al. 2011)
// is stronger on paper but needs ten rounds of 32-bit multiplies and more code for no
// observable benefit at our draw counts.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>

namespace creaturelab::core {

inline constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ULL;

// Stafford's Mix13 finaliser (the SplitMix64 output function): a bijection on 64 bits.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// FNV-1a (64-bit) of a purpose name, usable at compile time:
//   constexpr auto kWind = purposeId("web.wind_gusts");
constexpr std::uint64_t purposeId(std::string_view name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV offset basis
  for (char c : name) {
    h ^= static_cast<std::uint8_t>(c);
    h *= 0x100000001b3ULL;  // FNV prime
  }
  return h;
}

constexpr std::uint64_t streamKey(std::uint64_t seed, std::uint64_t purpose) {
  return mix64(mix64(seed + kGoldenGamma) ^ purpose);
}

constexpr std::uint64_t hash64(std::uint64_t seed, std::uint64_t purpose, std::uint64_t index) {
  return mix64(streamKey(seed, purpose) + (index + 1) * kGoldenGamma);
}

// Top 53 bits scaled by 2^-53: uniform on {0, 2^-53, ..., 1 - 2^-53}; never 1.0.
constexpr double toUniform01(std::uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

constexpr double uniform01(std::uint64_t seed, std::uint64_t purpose, std::uint64_t index) {
  return toUniform01(hash64(seed, purpose, index));
}

// Box–Muller (Box & Muller 1958): z = sqrt(-2 ln u1) cos(2 pi u2), with u1 in (0, 1] so the
// log is finite. Uses std::log/std::cos, so values are reproducible for one build on one
// platform (the determinism guarantee), not necessarily across libm versions.
inline double normalFromUniforms(double u1_in_0_1, double u2) {
  const double u1 = 1.0 - u1_in_0_1;  // [0,1) -> (0,1]
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// Standard normal number `index`; consumes the counters 2*index and 2*index + 1 of
// (seed, purpose). Do not mix uniform01 and normal draws on one (seed, purpose) unless
// the shared counters are intended; give each use its own purpose.
inline double normal(std::uint64_t seed, std::uint64_t purpose, std::uint64_t index) {
  return normalFromUniforms(uniform01(seed, purpose, 2 * index), uniform01(seed, purpose, 2 * index + 1));
}

// Sequential draws from one (seed, purpose): each draw consumes counters in order, so
// a Stream that only calls nextNormal() reproduces normal(seed, purpose, 0), (.., 1), ...
struct Stream {
  std::uint64_t seed = 0;
  std::uint64_t purpose = 0;
  std::uint64_t counter = 0;  // index of the next counter to consume

  constexpr Stream(std::uint64_t seed_in, std::uint64_t purpose_in, std::uint64_t first_counter = 0)
      : seed(seed_in), purpose(purpose_in), counter(first_counter) {}

  constexpr std::uint64_t nextU64() { return hash64(seed, purpose, counter++); }
  constexpr double nextUniform01() { return toUniform01(nextU64()); }
  // Uniform on [lo, hi); for extreme ranges rounding can give exactly hi.
  constexpr double nextUniform(double lo, double hi) { return lo + (hi - lo) * nextUniform01(); }
  double nextNormal() {
    const double u1 = nextUniform01();
    const double u2 = nextUniform01();
    return normalFromUniforms(u1, u2);
  }
};

}  // namespace creaturelab::core
