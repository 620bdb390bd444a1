#pragma once
// Target images from Netpbm files (thesis §6: "a simple bi-level image (a black and white image)
// containing mainly low frequency content", Figs. 6.6, 6.16): PBM (P1 text, P4 binary) and PGM (P2
// text, P5 binary, 8 or 16 bits). Dark pixels are the target: ink = 1 - grey / maxval, and a PBM
// 1 (black) is ink 1.
#include <cstdint>
#include <span>
#include <string>

#include "charlotte/raster.hpp"

namespace creaturelab::charlotte {

// Largest image accepted: 8192 pixels a side and 16 Mpixels in all (a 600 x 600 canvas needs far
// less; anything bigger is almost certainly a mistake and would only cost memory).
inline constexpr int kMaxImageSidePx = 8192;
inline constexpr long kMaxImagePixels = 16L * 1024 * 1024;

// Parses a whole Netpbm file held in memory. `name` (usually the path) starts every error message.
// Throws std::invalid_argument saying what is wrong: not P1/P2/P4/P5, malformed or missing header
// fields, zero or huge size, a bad maxval, a pixel above maxval, truncated pixel data.
Raster parseNetpbm(std::span<const std::uint8_t> bytes, const std::string& name);

// Reads and parses a file. Throws std::invalid_argument naming the path when it cannot be read.
Raster readNetpbmFile(const std::string& path);

}  // namespace creaturelab::charlotte
