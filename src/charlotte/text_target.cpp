#include "charlotte/text_target.hpp"

#include <pango/pangocairo.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "io/cairo_image.hpp"

namespace creaturelab::charlotte {
namespace {

// A private font map and layout per call: pango's default font map is shared per thread, and the
// runner calls this from several; a fresh map keeps each call independent of what ran before.
struct Layout {
  std::unique_ptr<PangoFontMap, decltype(&g_object_unref)> map{pango_cairo_font_map_new(), g_object_unref};
  std::unique_ptr<PangoContext, decltype(&g_object_unref)> context{pango_font_map_create_context(map.get()),
                                                                    g_object_unref};
  std::unique_ptr<PangoFontDescription, decltype(&pango_font_description_free)> desc;
  std::unique_ptr<PangoLayout, decltype(&g_object_unref)> layout{nullptr, g_object_unref};

  Layout(std::string_view text, std::string_view font)
      : desc(pango_font_description_from_string(std::string(font).c_str()), pango_font_description_free) {
    // No hinting, no sub-pixel colour: outlines scaled exactly, the same on every machine.
    cairo_font_options_t* options = cairo_font_options_create();
    cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
    pango_cairo_context_set_font_options(context.get(), options);
    cairo_font_options_destroy(options);
    // Laid out at 100 px; textTarget scales the ink box to the size asked for.
    pango_font_description_set_absolute_size(desc.get(), 100.0 * PANGO_SCALE);
    layout.reset(pango_layout_new(context.get()));
    pango_layout_set_font_description(layout.get(), desc.get());
    pango_layout_set_alignment(layout.get(), PANGO_ALIGN_CENTER);
    pango_layout_set_text(layout.get(), text.data(), int(text.size()));
  }

  // The family fontconfig actually gives for the description.
  std::string loadedFamily() const {
    std::unique_ptr<PangoFont, decltype(&g_object_unref)> f(
        pango_font_map_load_font(map.get(), context.get(), desc.get()), g_object_unref);
    if (!f) return "";
    std::unique_ptr<PangoFontDescription, decltype(&pango_font_description_free)> got(pango_font_describe(f.get()),
                                                                                      pango_font_description_free);
    const char* family = pango_font_description_get_family(got.get());
    return family ? family : "";
  }
};

std::string quoted(std::string_view text) { return "text \"" + std::string(text) + "\""; }

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string checkText(std::string_view text, std::string_view font) {
  const char* bad = nullptr;
  if (!g_utf8_validate(text.data(), gssize(text.size()), &bad)) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", unsigned(static_cast<unsigned char>(*bad)));
    return quoted(text) + ": not valid UTF-8 at byte " + hex + " (byte " + std::to_string(bad - text.data() + 1) + ")";
  }
  if (std::all_of(text.begin(), text.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); }))
    return quoted(text) + ": no letters to inscribe";
  Layout l(text, font);
  const char* asked = pango_font_description_get_family(l.desc.get());
  if (!asked) return "font \"" + std::string(font) + "\": names no font family (e.g. \"DejaVu Sans Bold\")";
  const std::string got = l.loadedFamily();
  if (lower(got) != lower(asked))
    return "font \"" + std::string(font) + "\": family \"" + asked + "\" is not installed (fontconfig offers \"" + got +
           "\" instead); install it (DejaVu: Debian fonts-dejavu-core) or name an installed one (fc-list)";
  if (pango_layout_get_unknown_glyphs_count(l.layout.get()) == 0) return "";
  // Name the first character the font lacks: lay each out alone.
  int place = 1;
  for (const char* p = text.data(); p < text.data() + text.size(); p = g_utf8_next_char(p), ++place) {
    const std::string_view ch(p, std::size_t(g_utf8_next_char(p) - p));
    if (ch == "\n") continue;
    Layout one(ch, font);
    if (pango_layout_get_unknown_glyphs_count(one.layout.get()) > 0)
      return quoted(text) + ": the font \"" + std::string(font) + "\" has no glyph for '" + std::string(ch) +
             "' (character " + std::to_string(place) + ")";
  }
  return quoted(text) + ": the font \"" + std::string(font) + "\" lacks a glyph for some character";
}

Raster textTarget(std::string_view text, std::string_view font, const CanvasMap& map, const Eigen::Vector2d& centre_m,
                  double width_m, double max_height_m) {
  if (std::string err = checkText(text, font); !err.empty()) throw std::invalid_argument(err);
  Layout l(text, font);
  PangoRectangle ink, logical;
  pango_layout_get_extents(l.layout.get(), &ink, &logical);
  const double ink_x = double(ink.x) / PANGO_SCALE, ink_y = double(ink.y) / PANGO_SCALE;
  const double ink_w = double(ink.width) / PANGO_SCALE, ink_h = double(ink.height) / PANGO_SCALE;
  double w = width_m * map.px_per_m, h = w * ink_h / ink_w;
  if (h > max_height_m * map.px_per_m) {
    h = max_height_m * map.px_per_m;
    w = h * ink_w / ink_h;
  }
  const double scale = w / ink_w;
  const Eigen::Vector2d c = map.toPx(centre_m);
  io::CairoImage canvas(map.size_px, map.size_px, io::PixelFormat::grey8);
  cairo_t* cr = canvas.cr();
  cairo_translate(cr, c.x() - w / 2, c.y() - h / 2);
  cairo_scale(cr, scale, scale);
  cairo_translate(cr, -ink_x, -ink_y);
  pango_cairo_update_context(cr, l.context.get());
  pango_layout_context_changed(l.layout.get());
  cairo_set_source_rgba(cr, 0, 0, 0, 1);
  pango_cairo_show_layout(cr, l.layout.get());
  Raster out(map.size_px, map.size_px);
  out.ink = canvas.coverage();
  return out;
}

}  // namespace creaturelab::charlotte
