// The image stages of the Charlotte's-web procedure (thesis seeds/orb-webs-mehla-2005.txt ch. 6):
// the built-in font, the Netpbm reader and its errors, dilation by a square (Figs. 6.7-6.8), the
// five-pixel band of a segment and its score (Fig. 6.9), and the PNG encoder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "charlotte/canvas.hpp"
#include "charlotte/font5x7.hpp"
#include "charlotte/morphology.hpp"
#include "charlotte/netpbm.hpp"
#include "charlotte/png.hpp"
#include "charlotte/score.hpp"

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

std::string rows(const ch::Raster& r) {
  std::string s;
  for (int y = 0; y < r.height; ++y) {
    for (int x = 0; x < r.width; ++x) s += r.at(x, y) > 0.5f ? '#' : '.';
    s += '\n';
  }
  return s;
}

}  // namespace

TEST(CharlotteFont, PigIsThreeGlyphsWithOneColumnBetween) {
  const ch::Raster r = ch::renderText("PIG");
  EXPECT_EQ(r.width, 3 * 5 + 2);
  EXPECT_EQ(r.height, 7);
  EXPECT_EQ(rows(r),
            "####...###...###.\n"
            "#...#...#...#...#\n"
            "#...#...#...#....\n"
            "####....#...#.###\n"
            "#.......#...#...#\n"
            "#.......#...#...#\n"
            "#......###...####\n");
}

TEST(CharlotteFont, LowerCaseIsDrawnAsCapitalsAndLinesAreCentred) {
  EXPECT_EQ(ch::renderText("pig").ink, ch::renderText("PIG").ink);
  const ch::Raster two = ch::renderText("SOME\nPIG");
  EXPECT_EQ(two.width, 4 * 6 - 1);
  EXPECT_EQ(two.height, 15);
  for (char c : std::string("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 .,!?'-")) EXPECT_EQ(ch::checkText(std::string("A") + c), "") << c;
}

TEST(CharlotteFont, ACharacterTheFontLacksIsNamed) {
  EXPECT_EQ(ch::checkText("PIG#"),
            "text \"PIG#\": the built-in font has no glyph for '#' (character 4); it draws " +
                std::string(ch::kFontRepertoire));
  EXPECT_NE(errorOf([] { ch::renderText("caf\xc3\xa9"); }).find("byte 0xC3 (character 4)"), std::string::npos);
  EXPECT_NE(ch::checkText("   ").find("no letters"), std::string::npos);
  EXPECT_NE(ch::checkText("").find("no letters"), std::string::npos);
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

TEST(CharlotteBand, FivePixelsAcrossEachLinePixelEachOnce) {
  // A horizontal segment through pixel row 10 from x = 3.5 to x = 12.5: columns 3..12, rows 8..12.
  std::set<std::pair<int, int>> seen;
  int count = 0;
  ch::forEachBandPixel({3.5, 10.5}, {12.5, 10.5}, 5, 100, 100, [&](int x, int y) {
    seen.insert({x, y});
    ++count;
    EXPECT_TRUE(x >= 3 && x <= 12 && y >= 8 && y <= 12) << x << "," << y;
  });
  EXPECT_EQ(count, 50);
  EXPECT_EQ(seen.size(), 50u);
  // Steep lines are widened along x; a-b and b-a give the same pixels; the canvas clips.
  std::set<std::pair<int, int>> ab, ba;
  ch::forEachBandPixel({2.2, 1.0}, {7.9, 30.0}, 5, 100, 100, [&](int x, int y) { ab.insert({x, y}); });
  ch::forEachBandPixel({7.9, 30.0}, {2.2, 1.0}, 5, 100, 100, [&](int x, int y) { ba.insert({x, y}); });
  EXPECT_EQ(ab, ba);
  EXPECT_EQ(ab.size(), 30u * 5u);
  int clipped = 0;
  ch::forEachBandPixel({0.5, 0.5}, {0.5, 9.5}, 5, 100, 100, [&](int, int) { ++clipped; });
  EXPECT_EQ(clipped, 10 * 3);
}

TEST(CharlotteScore, TheShareOfTheBandTheTargetCovers) {
  // Fig. 6.9 with the ratio read as target over source (score.hpp): a segment in a bar scores 10,
  // one beside it 0, one half in it 5.
  ch::Raster source(60, 40), target(60, 40);
  auto segment = [&](double x0, double x1, double y) {
    ch::drawLine(source, {x0, y}, {x1, y});
    return std::pair<Eigen::Vector2d, Eigen::Vector2d>{{x0, y}, {x1, y}};
  };
  for (int y = 0; y < 40; ++y)
    for (int x = 20; x < 40; ++x) target.at(x, y) = 1;
  const auto inside = segment(22.5, 37.5, 10.5), outside = segment(45.5, 55.5, 20.5), half = segment(10.5, 29.5, 30.5);
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

TEST(CharlottePng, ChunksAndChecksums) {
  // CRC-32 check value of "123456789" (ISO 3309).
  const std::string digits = "123456789";
  EXPECT_EQ(ch::crc32(reinterpret_cast<const std::uint8_t*>(digits.data()), digits.size()), 0xCBF43926u);
  ch::RgbImage img(3, 2, 200);
  img.rgb[0] = 255;
  const auto png = ch::encodePng(img);
  ASSERT_GT(png.size(), 8u + 25u + 12u + 12u);
  EXPECT_EQ(std::vector<std::uint8_t>(png.begin(), png.begin() + 8),
            (std::vector<std::uint8_t>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}));
  EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
  EXPECT_EQ(png[19], 3);  // width 3
  EXPECT_EQ(png[23], 2);  // height 2
  // The file ends with the empty IEND chunk and its well-known CRC AE 42 60 82.
  EXPECT_EQ(std::vector<std::uint8_t>(png.end() - 12, png.end()),
            (std::vector<std::uint8_t>{0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82}));
  EXPECT_THROW(ch::encodePng(ch::RgbImage{}), std::invalid_argument);
}
