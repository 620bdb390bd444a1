#pragma once
// Text targets (thesis §6: "the target image can either be text containing a few letters or a simple
// bi-level image"; Fig. 6.10: the letters P, I, G in heavy capitals), set in a real font by pango
// (libpango1.0-dev, fontconfig) and drawn anti-aliased by cairo. The thesis does not name its font;
// the default is DejaVu Sans Bold (Debian fonts-dejavu-core), heavy letters as in Fig. 6.10.
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "charlotte/canvas.hpp"
#include "charlotte/raster.hpp"

namespace creaturelab::charlotte {

inline constexpr std::string_view kDefaultFont = "DejaVu Sans Bold";

// "" when `text` can be inscribed in `font` (a pango font description, e.g. "DejaVu Sans Bold"),
// else one sentence saying why: the text is empty or blank ("no letters"), is not valid UTF-8 (the
// byte and its place named), the font is not installed (fontconfig would silently substitute
// another, which would make the run depend on the machine), or the font has no glyph for a
// character (named, with its place). '\n' starts a new line.
std::string checkText(std::string_view text, std::string_view font = kDefaultFont);

// The text on the canvas: its lines centred on each other, the ink box of all letters centred on
// centre_m, width_m wide and the height following the letters' aspect ratio but at most max_height_m
// (the width shrinks to keep the aspect then). Ink 1 inside the letters, anti-aliased edges.
// Hinting is off, so the letters depend only on the font file and these numbers.
// Throws std::invalid_argument with checkText()'s message.
Raster textTarget(std::string_view text, std::string_view font, const CanvasMap& map, const Eigen::Vector2d& centre_m,
                  double width_m, double max_height_m);

}  // namespace creaturelab::charlotte
