// Text helpers: edit distance, suggestions, number formatting, timestamps.
#include "core/text.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <regex>

namespace cl = creaturelab::core;

TEST(Text, EditDistanceClassicCases) {
  EXPECT_EQ(cl::editDistance("", ""), 0u);
  EXPECT_EQ(cl::editDistance("abc", ""), 3u);
  EXPECT_EQ(cl::editDistance("", "abc"), 3u);
  EXPECT_EQ(cl::editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(cl::editDistance("flaw", "lawn"), 2u);
  EXPECT_EQ(cl::editDistance("cycles", "cycles"), 0u);
  EXPECT_EQ(cl::editDistance("grid_cels", "grid_cells"), 1u);
}

TEST(Text, ClosestMatchSuggestsNearKeysOnly) {
  const std::vector<std::string> keys = {"grid_cells", "cycles", "contraction_hz", "expansion"};
  EXPECT_EQ(cl::closestMatch("grid_cels", keys), "grid_cells");
  EXPECT_EQ(cl::closestMatch("cycels", keys), "cycles");
  EXPECT_EQ(cl::closestMatch("contraction_frequency", keys), "");
  EXPECT_EQ(cl::closestMatch("zzz", keys), "");
  EXPECT_EQ(cl::closestMatch("anything", {}), "");
  // Short words still get distance 2.
  EXPECT_EQ(cl::closestMatch("ab", {"xy", "ba"}), "xy");  // both distance 2: earlier wins
}

TEST(Text, DidYouMeanNamesAMatchOrAPrefixedName) {
  const std::vector<std::string> keys = {"spring_k_n_per_m", "cycles"};
  EXPECT_EQ(cl::didYouMean("cycels", keys), " (did you mean 'cycles'?)");
  // Too far by edit distance, but the name with its unit spelled out starts with it.
  EXPECT_EQ(cl::didYouMean("spring_k", keys), " (did you mean 'spring_k_n_per_m'?)");
  EXPECT_EQ(cl::didYouMean("sp", keys), "");  // a prefix must be 3 characters or more
  EXPECT_EQ(cl::didYouMean("unrelated", keys), "");
}

TEST(Text, FormatNumberIsShortestRoundTrip) {
  EXPECT_EQ(cl::formatNumber(0.1), "0.1");
  EXPECT_EQ(cl::formatNumber(3.0), "3");
  EXPECT_EQ(cl::formatNumber(-2.5), "-2.5");
  EXPECT_EQ(cl::formatNumber(1e-7), "1e-07");
  EXPECT_EQ(cl::formatNumber(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(cl::formatNumber(std::nan("")), "nan");
  for (double v : {1.0 / 3.0, 2.0 / 3.0, 6.02214076e23, 5e-324, std::numeric_limits<double>::max()}) {
    const std::string text = cl::formatNumber(v);
    double back = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    EXPECT_EQ(back, v) << text;
  }
}

TEST(Text, IsoTimeUtcNowHasIsoShape) {
  const std::string now = cl::isoTimeUtcNow();
  EXPECT_TRUE(std::regex_match(now, std::regex(R"(\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}Z)"))) << now;
}
