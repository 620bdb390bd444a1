#pragma once
// A built-in 5x7 bitmap font for the target text (thesis §6: "the target image can either be text
// containing a few letters or a simple bi-level image"; Fig. 6.10: the letters P, I, G). The glyphs
// follow the classic 5x7 dot-matrix character set (as in the HD44780 display ROM).
#include <string>
#include <string_view>

#include "charlotte/raster.hpp"

namespace creaturelab::charlotte {

inline constexpr int kGlyphWidth = 5;   // font pixels
inline constexpr int kGlyphHeight = 7;  // font pixels
// Characters the font draws, in words (for error messages).
inline constexpr std::string_view kFontRepertoire = "A-Z (a-z are drawn as capitals), 0-9, space and . , ! ? ' -";

// "" when every character of `text` has a glyph, else a sentence naming the first that has none,
// e.g. "text \"PIG#\": the built-in font has no glyph for '#' (character 4); it draws A-Z ...".
// '\n' starts a new line. An empty text (or one of spaces only) is an error too: nothing to inscribe.
std::string checkText(std::string_view text);

// The text at one raster pixel per font pixel: 5 x 7 cells, one empty column between characters
// and one empty row between lines, lines centred; ink 1 on the letters, 0 elsewhere.
// Throws std::invalid_argument with checkText()'s message.
Raster renderText(std::string_view text);

}  // namespace creaturelab::charlotte
