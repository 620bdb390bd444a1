// Perlin's improved noise (core/improved_noise.hpp) against the reference implementation's output
// and its defining properties: zero on the lattice, periodic where asked, seeded, bounded, smooth.
#include "core/improved_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cl = creaturelab::core;

TEST(ImprovedNoise, ReferenceValue) {
  // Perlin's Java reference (2002) prints 0.13691995878400012 at (3.14, 42, 7) in IEEE doubles
  // (Rosetta Code, "Perlin noise"): the same arithmetic in the same order gives the same bits.
  EXPECT_EQ(cl::ImprovedNoise::reference()(3.14, 42, 7), 0.13691995878400012);
}

TEST(ImprovedNoise, ZeroOnTheLattice) {
  const auto reference = cl::ImprovedNoise::reference(), seeded = cl::ImprovedNoise::seeded(3);
  for (int x = -3; x < 4; ++x)
    for (int y = 0; y < 5; ++y) {
      EXPECT_EQ(reference(x, y, 7), 0.0);
      EXPECT_EQ(seeded(x, y, -2), 0.0);
    }
}

TEST(ImprovedNoise, PeriodicWhereAsked) {
  auto n = cl::ImprovedNoise::seeded(11);
  EXPECT_FALSE(n.setPeriods(256, 6, 256));  // not a power of two
  ASSERT_TRUE(n.setPeriods(256, 8, 256));
  for (double x : {0.1, 0.77, 1.9})
    for (double y : {0.0, 0.35, 3.5, 7.99})
      for (double z : {0.0, 0.013, 0.5}) {
        // (y + 8) - floor(y + 8) rounds differently from y - floor(y): equal to round-off
        EXPECT_NEAR(n(x, y + 8, z), n(x, y, z), 1e-14);
        EXPECT_NEAR(n(x, y - 16, z), n(x, y, z), 1e-14);
      }
  // ... and a period of 256 is the reference's own lattice.
  auto r = cl::ImprovedNoise::reference();
  ASSERT_TRUE(r.setPeriods(256, 256, 256));
  EXPECT_EQ(r(3.14, 42, 7), 0.13691995878400012);
}

TEST(ImprovedNoise, SeedsAreDeterministicAndDistinct) {
  const auto a = cl::ImprovedNoise::seeded(7), b = cl::ImprovedNoise::seeded(7), c = cl::ImprovedNoise::seeded(8);
  int differ = 0;
  for (int k = 0; k < 200; ++k) {
    const double x = 0.37 * k, y = 0.11 * k + 0.5, z = 0.013 * k + 0.25;
    EXPECT_EQ(a(x, y, z), b(x, y, z));
    differ += a(x, y, z) != c(x, y, z);
  }
  EXPECT_GT(differ, 150);
}

TEST(ImprovedNoise, BoundedAndSmooth) {
  const auto n = cl::ImprovedNoise::seeded(5);
  double largest = 0, steepest = 0;
  for (int k = 0; k < 20000; ++k) {
    const double x = 0.0137 * k, y = 0.0071 * k + 0.3, z = 0.0029 * k + 0.7, h = 1e-4;
    largest = std::max(largest, std::abs(n(x, y, z)));
    steepest = std::max(steepest, std::abs(n(x + h, y, z) - n(x, y, z)) / h);
  }
  EXPECT_LE(largest, 1.05);  // |gradient| <= sqrt(2) per corner; in practice within about [-1, 1]
  EXPECT_GT(largest, 0.3);
  EXPECT_LT(steepest, 5.0);  // C1 (and C2): no jumps at cell faces
}
