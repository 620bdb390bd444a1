// The image stages of the Charlotte's-web procedure (Mehla 2005 ch. 6):
// text targets (pango), the Netpbm reader and its errors, dilation by a square (Figs. 6.7-6.8), the
// capture, the five-pixel band of a segment and its score (Fig. 6.9) (cairo), and the renders' PNG.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "charlotte/canvas.hpp"
#include "charlotte/morphology.hpp"
#include "charlotte/netpbm.hpp"
#include "charlotte/render.hpp"
#include "charlotte/score.hpp"
#include "charlotte/text_target.hpp"

namespace ch = creaturelab::charlotte;

namespace {

std::vector<std::uint8_t> bytes(const std::string& s) { return {s.begin(), s.end()}; }

// The message of the std::invalid_argument that f throws ("" if none).
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

namespace {

// A 200-pixel canvas over 1 m, centred on the origin.
ch::CanvasMap unitCanvas() {
  ch::CanvasMap m;
  m.size_px = 200;
  m.left_m = -0.5, m.top_m = 0.5, m.px_per_m = 200;
  return m;
}

// Bounding box (x0, y0, x1, y1) of the pixels with ink >= 0.5.
std::array<int, 4> inkBox(const ch::Raster& r) {
  std::array<int, 4> b{r.width, r.height, -1, -1};
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x)
      if (r.at(x, y) >= 0.5f) b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x), std::max(b[3], y)};
  return b;
}

}  // namespace

TEST(CharlotteText, PigFillsTheBoxAskedForCentredAndAntiAliased) {
  const auto map = unitCanvas();
  const ch::Raster r = ch::textTarget("PIG", ch::kDefaultFont, map, {0, 0}, 0.6, 0.5);
  // 0.6 m wide = 120 px, centred on pixel 100; capitals are wider than tall here, so the width binds.
  const auto b = inkBox(r);
  EXPECT_NEAR(b[0], 40, 2);
  EXPECT_NEAR(b[2], 159, 2);
  EXPECT_NEAR(0.5 * (b[1] + b[3]), 100, 2);
  EXPECT_LT(b[3] - b[1], 120);
  // Anti-aliased edges (grey levels) and solid strokes; letters cover a good part of their box.
  int grey = 0, solid = 0;
  for (float v : r.ink) grey += v > 0.05f && v < 0.95f, solid += v >= 0.95f;
  EXPECT_GT(grey, 50);
  EXPECT_GT(solid, 0.25 * (b[2] - b[0]) * (b[3] - b[1]));
  // Deterministic: the same call gives the same pixels.
  EXPECT_EQ(ch::textTarget("PIG", ch::kDefaultFont, map, {0, 0}, 0.6, 0.5).ink, r.ink);
  // Two lines are taller than one; max_height binds then and the width shrinks.
  const auto two = inkBox(ch::textTarget("SOME\nPIG", ch::kDefaultFont, map, {0, 0}, 0.6, 0.3));
  EXPECT_NEAR(two[3] - two[1], 60, 2);
  EXPECT_LT(two[2] - two[0], 119);
}

TEST(CharlotteText, BadTextOrFontIsNamed) {
  EXPECT_EQ(ch::checkText("PIG"), "");
  EXPECT_EQ(ch::checkText("caf\xc3\xa9 #1"), "");  // a real font draws accents and symbols
  EXPECT_NE(ch::checkText("   ").find("no letters"), std::string::npos);
  EXPECT_NE(ch::checkText("").find("no letters"), std::string::npos);
  EXPECT_NE(ch::checkText("PI\xff").find("not valid UTF-8 at byte 0xFF (byte 3)"), std::string::npos);
  const std::string missing = ch::checkText("PIG", "No Such Font Family Bold");
  EXPECT_NE(missing.find("\"No Such Font Family\" is not installed"), std::string::npos) << missing;
  // Private-use code point U+E000: no glyph in DejaVu.
  const std::string lacks = ch::checkText("PI\xee\x80\x80G");
  EXPECT_NE(lacks.find("has no glyph for"), std::string::npos) << lacks;
  EXPECT_NE(lacks.find("(character 3)"), std::string::npos) << lacks;
  EXPECT_THROW(ch::textTarget("", ch::kDefaultFont, unitCanvas(), {0, 0}, 0.5, 0.5), std::invalid_argument);
}

TEST(CharlotteNetpbm, TextFormatsWithComments) {
  // P1: 1 = black = ink; digits may run together.
  const ch::Raster a = ch::parseNetpbm(bytes("P1\n# a comment\n3 2\n1 0 1\n010\n"), "a.pbm");
  EXPECT_EQ(a.width, 3);
  EXPECT_EQ(a.height, 2);
  EXPECT_EQ(a.ink, (std::vector<float>{1, 0, 1, 0, 1, 0}));
  // P2: ink = 1 - grey / maxval (dark = target).
  const ch::Raster b = ch::parseNetpbm(bytes("P2 2 1 4\n0 # black\n 4\n"), "b.pgm");
  EXPECT_EQ(b.ink, (std::vector<float>{1, 0}));
}

TEST(CharlotteNetpbm, BinaryFormats) {
  // P4: rows padded to whole bytes, most significant bit first.
  std::string p4 = "P4\n10 2\n";
  p4 += char(0b10000000), p4 += char(0b01000000), p4 += char(0b00000000), p4 += char(0b11000000);
  const ch::Raster a = ch::parseNetpbm(bytes(p4), "a.pbm");
  EXPECT_EQ(a.at(0, 0), 1);
  EXPECT_EQ(a.at(9, 0), 1);
  EXPECT_EQ(a.at(1, 0), 0);
  EXPECT_EQ(a.at(8, 1), 1);
  EXPECT_EQ(a.at(9, 1), 1);
  EXPECT_FLOAT_EQ(a.sum(), 4);
  // P5, 8 and 16 bits (big-endian).
  std::string p5 = "P5 2 1 255\n";
  p5 += char(0), p5 += char(255);
  EXPECT_EQ(ch::parseNetpbm(bytes(p5), "b.pgm").ink, (std::vector<float>{1, 0}));
  std::string p5w = "P5 1 1 65535\n";
  p5w += char(0x80), p5w += char(0x00);
  EXPECT_NEAR(ch::parseNetpbm(bytes(p5w), "c.pgm").ink[0], 1 - 32768.0 / 65535.0, 1e-6);
}

TEST(CharlotteNetpbm, BadImagesSayWhatIsWrong) {
  auto err = [](const std::string& text) { return errorOf([&] { ch::parseNetpbm(bytes(text), "t.pgm"); }); };
  EXPECT_EQ(err(""), "t.pgm: the file is empty; expected a PBM or PGM image (P1, P2, P4 or P5)");
  EXPECT_NE(err("\x89PNG....").find("t.pgm: not a PBM or PGM image"), std::string::npos);
  EXPECT_NE(err("P3 1 1 255 0 0 0").find("expected P1, P2"), std::string::npos);
  EXPECT_EQ(err("P1 0 5"), "t.pgm: the image is 0 x 5 pixels; it needs at least one pixel");
  EXPECT_NE(err("P5 100000 100000 255\n").find("too large"), std::string::npos);
  EXPECT_NE(err("P5 5000 5000 255\n").find("too large"), std::string::npos);  // 25 Mpixels
  EXPECT_NE(err("P1 2").find("ends before the height"), std::string::npos);
  EXPECT_NE(err("P2 2 x").find("height is not a number"), std::string::npos);
  EXPECT_NE(err("P2 1 1 0 0").find("maxval 0"), std::string::npos);
  EXPECT_EQ(err("P2 2 1 10 3 11"), "t.pgm: pixel at row 1, column 2 is 11, above maxval 10");
  EXPECT_NE(err("P1 2 2 1 0 1").find("ends at row 2, column 2"), std::string::npos);
  EXPECT_NE(err("P5 4 4 255\nabc").find("truncated: the pixel data needs 16 bytes, the file has 3"), std::string::npos);
  EXPECT_NE(err("P4 8 1").find("one whitespace byte"), std::string::npos);
}

TEST(CharlotteNetpbm, UnreadableFilesAreNamed) {
  EXPECT_EQ(errorOf([] { ch::readNetpbmFile("/nonexistent/dir/pig.pbm"); }),
            "/nonexistent/dir/pig.pbm: cannot be read (No such file or directory)");
  EXPECT_NE(errorOf([] { ch::readNetpbmFile(""); }).find("no image file given"), std::string::npos);
  const std::string dir = std::filesystem::temp_directory_path().string();
  EXPECT_NE(errorOf([&] { ch::readNetpbmFile(dir); }).find(dir + ": cannot be read"), std::string::npos);
  const auto path = std::filesystem::temp_directory_path() / ("charlotte_read_" + std::to_string(::getpid()) + ".pbm");
  std::ofstream(path) << "P1 2 1\n1 0\n";
  EXPECT_EQ(ch::readNetpbmFile(path.string()).ink, (std::vector<float>{1, 0}));
  std::filesystem::remove(path);
}

TEST(CharlotteDilate, OnePixelBecomesTheStructuringElement) {
  ch::Raster r(20, 20);
  r.at(10, 10) = 1;
  const ch::Raster d = ch::dilate(r, 7);
  EXPECT_FLOAT_EQ(d.sum(), 49);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) EXPECT_EQ(d.at(x, y), (std::abs(x - 10) <= 3 && std::abs(y - 10) <= 3) ? 1 : 0);
  EXPECT_EQ(ch::dilate(r, 1).ink, r.ink);
  // Grey levels: a max filter, clipped at the border; dilating twice by 3 = once by 5.
  ch::Raster g(9, 9);
  g.at(0, 0) = 0.25f, g.at(8, 8) = 0.75f;
  EXPECT_FLOAT_EQ(ch::dilate(g, 3).sum(), 4 * 0.25f + 4 * 0.75f);
  EXPECT_EQ(ch::dilate(ch::dilate(g, 3), 3).ink, ch::dilate(g, 5).ink);
}

TEST(CharlotteBand, ThePixelsWhoseCentresLieInTheFivePixelRectangle) {
  // A horizontal segment on y = 10.5 from x = 3 to x = 13: centres 3.5..12.5 along, 8.5..12.5 across.
  std::set<std::pair<int, int>> seen;
  for (int i : ch::bandPixels({3.0, 10.5}, {13.0, 10.5}, 5, 100, 100)) {
    const int x = i % 100, y = i / 100;
    seen.insert({x, y});
    EXPECT_TRUE(x >= 3 && x <= 12 && y >= 8 && y <= 12) << x << "," << y;
  }
  EXPECT_EQ(seen.size(), 50u);
  // A slanted band holds about length x width pixels (a rotated rectangle, not a sheared one);
  // a-b and b-a give the same pixels; the canvas clips.
  const auto ab = ch::bandPixels({2.2, 1.0}, {7.9, 30.0}, 5, 100, 100);
  EXPECT_EQ(ab, ch::bandPixels({7.9, 30.0}, {2.2, 1.0}, 5, 100, 100));
  const double area = std::hypot(5.7, 29.0) * 5;
  EXPECT_NEAR(double(ab.size()), area, 0.06 * area);
  EXPECT_TRUE(std::is_sorted(ab.begin(), ab.end()));
  EXPECT_EQ(ch::bandPixels({0.5, 0.0}, {0.5, 10.0}, 5, 100, 100).size(), 10u * 3u);
}

TEST(CharlotteCapture, OnePixelLinesNotAntiAliased) {
  // A horizontal and a vertical line through pixel centres: exactly one pixel thick, ink 1, crossing once.
  const ch::Raster r = ch::captureLines(40, 40, {{{5.0, 10.5}, {35.0, 10.5}}, {{20.5, 2.0}, {20.5, 30.0}}});
  for (float v : r.ink) EXPECT_TRUE(v == 0.0f || v == 1.0f);
  EXPECT_FLOAT_EQ(r.sum(), 30 + 28 - 1);
  EXPECT_FLOAT_EQ(r.at(20, 10), 1);
  EXPECT_FLOAT_EQ(r.at(21, 11), 0);
  EXPECT_FLOAT_EQ(r.at(21, 9), 0);
}

TEST(CharlotteScore, TheShareOfTheBandTheTargetCovers) {
  // Fig. 6.9 with the ratio read as target over source (score.hpp): a segment in a bar scores 10,
  // one beside it 0, one half in it 5.
  ch::Raster source(60, 40), target(60, 40);
  std::vector<ch::LinePx> lines;
  auto segment = [&](double x0, double x1, double y) {
    lines.push_back({{x0, y}, {x1, y}});
    return lines.back();
  };
  for (int y = 0; y < 40; ++y)
    for (int x = 20; x < 40; ++x) target.at(x, y) = 1;
  const auto inside = segment(22.0, 38.0, 10.5), outside = segment(45.0, 56.0, 20.5), half = segment(10.0, 30.0, 30.5);
  source = ch::captureLines(60, 40, lines);
  const ch::Raster sd = ch::dilate(source, 7), td = ch::dilate(target, 7);
  auto score = [&](const auto& s) { return ch::scoreSegment(sd, td, s.first, s.second, 5).score; };
  EXPECT_EQ(score(inside), 10);
  EXPECT_EQ(score(outside), 0);
  // The dilated bar starts at x = 17: columns 17..29 of 10..29 are covered, 13 of 20.
  EXPECT_EQ(score(half), 6);
  const auto s = ch::scoreSegment(sd, td, inside.first, inside.second, 5);
  EXPECT_EQ(s.band_pixels, 16 * 5);
  EXPECT_DOUBLE_EQ(s.source_total, s.band_pixels);  // the dilated strand fills its own band
}

TEST(CharlotteRender, AlphaBlendedStrandsOnABackgroundAsPng) {
  ch::Painter p(20, 10, {1.0f, 1.0f, 1.0f});
  p.line({2.0, 5.0}, {18.0, 5.0}, 2.0f, {0.0f, 0.0f, 0.0f}, 0.5f);  // half-transparent black on white
  ch::Raster ink(20, 10);
  ink.at(0, 0) = 1;
  p.wash(ink, {1.0f, 0.0f, 0.0f}, 1.0f);  // one red pixel
  const auto rgb = p.rgb();
  auto at = [&](int x, int y, int c) { return int(rgb[(std::size_t(y) * 20 + std::size_t(x)) * 3 + std::size_t(c)]); };
  EXPECT_NEAR(at(10, 4, 0), 128, 1);  // inside the stroke: white halfway to black
  EXPECT_EQ(at(10, 0, 1), 255);       // background untouched
  EXPECT_EQ(at(0, 0, 0), 255);        // washed red
  EXPECT_EQ(at(0, 0, 1), 0);
  const auto png = p.png();
  ASSERT_GT(png.size(), 8u + 25u + 12u);
  EXPECT_EQ(std::vector<std::uint8_t>(png.begin(), png.begin() + 8),
            (std::vector<std::uint8_t>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}));
  EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
  EXPECT_EQ(png[19], 20);  // width
  EXPECT_EQ(png[23], 10);  // height
  EXPECT_EQ(std::string(png.end() - 8, png.end() - 4), "IEND");
}
