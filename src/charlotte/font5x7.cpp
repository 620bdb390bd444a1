#include "charlotte/font5x7.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <vector>

namespace creaturelab::charlotte {
namespace {

struct Glyph {
  char c;
  std::array<const char*, kGlyphHeight> rows;  // '#' = ink, top row first
};

// clang-format off
constexpr Glyph kGlyphs[] = {
  {'A', {".###.", "#...#", "#...#", "#...#", "#####", "#...#", "#...#"}},
  {'B', {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."}},
  {'C', {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."}},
  {'D', {"###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###.."}},
  {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
  {'F', {"#####", "#....", "#....", "####.", "#....", "#....", "#...."}},
  {'G', {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"}},
  {'H', {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
  {'I', {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
  {'J', {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."}},
  {'K', {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"}},
  {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
  {'M', {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"}},
  {'N', {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"}},
  {'O', {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
  {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
  {'Q', {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"}},
  {'R', {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"}},
  {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
  {'T', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
  {'U', {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
  {'V', {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
  {'W', {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."}},
  {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
  {'Y', {"#...#", "#...#", "#...#", ".#.#.", "..#..", "..#..", "..#.."}},
  {'Z', {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"}},
  {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
  {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
  {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
  {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
  {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
  {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
  {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
  {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
  {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
  {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
  {' ', {".....", ".....", ".....", ".....", ".....", ".....", "....."}},
  {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
  {',', {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."}},
  {'!', {"..#..", "..#..", "..#..", "..#..", "..#..", ".....", "..#.."}},
  {'?', {".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#.."}},
  {'\'', {".##..", "..#..", ".#...", ".....", ".....", ".....", "....."}},
  {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
};
// clang-format on

const Glyph* findGlyph(char c) {
  const char upper = (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c;
  for (const Glyph& g : kGlyphs)
    if (g.c == upper) return &g;
  return nullptr;
}

std::string describeChar(char c) {
  const auto u = static_cast<unsigned char>(c);
  char buf[32];
  if (u >= 0x20 && u < 0x7f) std::snprintf(buf, sizeof buf, "'%c'", c);
  else std::snprintf(buf, sizeof buf, "byte 0x%02X", unsigned(u));  // a control character or part of UTF-8
  return buf;
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  for (;;) {
    const std::size_t nl = text.find('\n', start);
    lines.push_back(text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start));
    if (nl == std::string_view::npos) return lines;
    start = nl + 1;
  }
}

}  // namespace

std::string checkText(std::string_view text) {
  bool any_ink = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') continue;
    if (!findGlyph(text[i]))
      return "text \"" + std::string(text) + "\": the built-in font has no glyph for " + describeChar(text[i]) +
             " (character " + std::to_string(i + 1) + "); it draws " + std::string(kFontRepertoire);
    any_ink |= text[i] != ' ';
  }
  if (!any_ink) return "text \"" + std::string(text) + "\" has no letters to inscribe; give at least one character";
  return "";
}

Raster renderText(std::string_view text) {
  if (std::string err = checkText(text); !err.empty()) throw std::invalid_argument(err);
  const auto lines = splitLines(text);
  auto columns = [](std::string_view line) { return line.empty() ? 0 : int(line.size()) * (kGlyphWidth + 1) - 1; };
  int width = 0;
  for (auto line : lines) width = std::max(width, columns(line));
  const int height = int(lines.size()) * (kGlyphHeight + 1) - 1;
  Raster r(width, height);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const int x0 = (width - columns(lines[l])) / 2, y0 = int(l) * (kGlyphHeight + 1);
    for (std::size_t i = 0; i < lines[l].size(); ++i) {
      const Glyph& g = *findGlyph(lines[l][i]);
      for (int y = 0; y < kGlyphHeight; ++y)
        for (int x = 0; x < kGlyphWidth; ++x)
          if (g.rows[y][x] == '#') r.at(x0 + int(i) * (kGlyphWidth + 1) + x, y0 + y) = 1.0f;
    }
  }
  return r;
}

}  // namespace creaturelab::charlotte
