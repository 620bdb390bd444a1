#include "charlotte/render.hpp"

namespace creaturelab::charlotte {

Painter::Painter(int width, int height, const Rgb& background) : image_(width, height, io::PixelFormat::rgb24) {
  cairo_t* cr = image_.cr();
  cairo_set_source_rgb(cr, background[0], background[1], background[2]);
  cairo_paint(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
}

void Painter::wash(const Raster& ink, const Rgb& colour, float alpha) {
  io::CairoImage mask = io::CairoImage::fromCoverage(ink.width, ink.height, ink.ink);
  cairo_t* cr = image_.cr();
  // Paint the colour through the ink as a mask, with the extra alpha as a group opacity.
  cairo_push_group(cr);
  cairo_set_source_rgb(cr, colour[0], colour[1], colour[2]);
  cairo_mask_surface(cr, mask.surface(), 0, 0);
  cairo_pop_group_to_source(cr);
  cairo_paint_with_alpha(cr, alpha);
}

void Painter::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, float width_px, const Rgb& colour, float alpha) {
  cairo_t* cr = image_.cr();
  cairo_set_source_rgba(cr, colour[0], colour[1], colour[2], alpha);
  cairo_set_line_width(cr, width_px);
  cairo_move_to(cr, a.x(), a.y());
  cairo_line_to(cr, b.x(), b.y());
  cairo_stroke(cr);
}

std::vector<std::uint8_t> Painter::rgb() { return image_.rgb(); }
std::vector<std::uint8_t> Painter::png() { return image_.png(); }

}  // namespace creaturelab::charlotte
