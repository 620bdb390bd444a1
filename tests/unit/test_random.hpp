#pragma once
// Random test inputs: uniform doubles from the top 53 bits of std::mt19937_64, so every standard
// library draws the same numbers from a seed.
#include <random>

namespace creaturelab::test {

inline double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

inline double uniform(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }

}  // namespace creaturelab::test
