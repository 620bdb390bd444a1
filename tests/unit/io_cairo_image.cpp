// io/cairo_image.hpp: coverage in and out, RGB24 pixels, PNG bytes from cairo, bad sizes.
#include "io/cairo_image.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace io = creaturelab::io;

TEST(CairoImage, CoverageRoundTripsAtEightBits) {
  const std::vector<float> in = {0.0f, 0.25f, 0.5f, 1.0f, 2.0f, -1.0f};  // out of [0, 1] is clamped
  io::CairoImage img = io::CairoImage::fromCoverage(3, 2, in);
  const std::vector<float> out = img.coverage();
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(out[i], in[i], 0.5 / 255 + 1e-6) << i;  // rounded to the nearest byte
  EXPECT_EQ(out[4], 1.0f);
  EXPECT_EQ(out[5], 0.0f);
  EXPECT_THROW(io::CairoImage::fromCoverage(3, 3, in), std::invalid_argument);
}

TEST(CairoImage, FilledRectangleIsExactWithoutAntialiasing) {
  io::CairoImage img(10, 10, io::PixelFormat::grey8);
  cairo_set_antialias(img.cr(), CAIRO_ANTIALIAS_NONE);
  cairo_rectangle(img.cr(), 2, 3, 4, 5);  // pixels x 2..5, y 3..7
  cairo_fill(img.cr());
  const auto c = img.coverage();
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) EXPECT_EQ(c[std::size_t(y * 10 + x)], (x >= 2 && x < 6 && y >= 3 && y < 8) ? 1.0f : 0.0f);
  EXPECT_THROW(img.rgb(), std::logic_error);
}

TEST(CairoImage, RgbPixelsAndPngBytes) {
  io::CairoImage img(4, 3, io::PixelFormat::rgb24);
  cairo_set_source_rgb(img.cr(), 1.0, 0.5, 0.0);
  cairo_paint(img.cr());
  const auto rgb = img.rgb();
  ASSERT_EQ(rgb.size(), 4u * 3u * 3u);
  EXPECT_EQ(rgb[0], 255);
  EXPECT_NEAR(rgb[1], 128, 1);
  EXPECT_EQ(rgb[2], 0);
  const auto png = img.png();
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(std::string(png.begin() + 1, png.begin() + 4), "PNG");
  EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
  EXPECT_EQ(png[19], 4);  // width
  EXPECT_EQ(png[23], 3);  // height
  EXPECT_THROW(img.coverage(), std::logic_error);
}

TEST(CairoImage, BadSizesAreNamed) {
  try {
    io::CairoImage img(0, 5, io::PixelFormat::grey8);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("0 x 5 pixels"), std::string::npos) << e.what();
  }
  EXPECT_THROW(io::CairoImage(40000, 40000, io::PixelFormat::rgb24), std::runtime_error);  // beyond cairo's 32767
}
