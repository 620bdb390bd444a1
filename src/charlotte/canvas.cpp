#include "charlotte/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/cairo_image.hpp"

namespace creaturelab::charlotte {

CanvasMap canvasOver(const springs::Points<3>& x_m, int size_px, double margin_fraction) {
  if (x_m.cols() == 0) throw std::invalid_argument("canvasOver: no particles");
  const Eigen::Vector2d lo = x_m.topRows<2>().rowwise().minCoeff(), hi = x_m.topRows<2>().rowwise().maxCoeff();
  const Eigen::Vector2d centre = 0.5 * (lo + hi);
  const double side = std::max((hi - lo).maxCoeff(), 1e-9) * (1 + 2 * margin_fraction);
  CanvasMap m;
  m.size_px = size_px;
  m.px_per_m = size_px / side;
  m.left_m = centre.x() - side / 2;
  m.top_m = centre.y() + side / 2;
  return m;
}

Raster captureLines(int width, int height, const std::vector<LinePx>& lines, double width_px) {
  io::CairoImage img(width, height, io::PixelFormat::grey8);
  cairo_t* cr = img.cr();
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  cairo_set_line_width(cr, width_px);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_set_source_rgba(cr, 0, 0, 0, 1);
  // One path: cairo strokes every sub-path and unites them, so where strands cross the ink stays 1.
  for (const auto& [a, b] : lines) {
    cairo_move_to(cr, a.x(), a.y());
    cairo_line_to(cr, b.x(), b.y());
  }
  cairo_stroke(cr);
  Raster r(width, height);
  r.ink = img.coverage();
  return r;
}

std::vector<int> bandPixels(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px, int band_px, int width,
                            int height) {
  if (band_px < 1) throw std::invalid_argument("bandPixels: the band must be at least one pixel wide");
  // Stroke on a small image over the band's bounding box only (a segment is tens of pixels long on a
  // 600-pixel canvas); the same orientation for a-b and b-a, so both give the same pixels.
  const bool swap = b_px.x() < a_px.x() || (b_px.x() == a_px.x() && b_px.y() < a_px.y());
  const Eigen::Vector2d p = swap ? b_px : a_px, q = swap ? a_px : b_px;
  const double reach = band_px / 2.0 + 1.0;
  const int x0 = std::max(0, int(std::floor(std::min(p.x(), q.x()) - reach)));
  const int y0 = std::max(0, int(std::floor(std::min(p.y(), q.y()) - reach)));
  const int x1 = std::min(width, int(std::ceil(std::max(p.x(), q.x()) + reach)));
  const int y1 = std::min(height, int(std::ceil(std::max(p.y(), q.y()) + reach)));
  std::vector<int> out;
  if (x1 <= x0 || y1 <= y0) return out;
  io::CairoImage img(x1 - x0, y1 - y0, io::PixelFormat::grey8);
  cairo_t* cr = img.cr();
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  cairo_set_line_width(cr, band_px);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_move_to(cr, p.x() - x0, p.y() - y0);
  cairo_line_to(cr, q.x() - x0, q.y() - y0);
  cairo_stroke(cr);
  const std::vector<float> c = img.coverage();
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (c[std::size_t(y - y0) * std::size_t(x1 - x0) + std::size_t(x - x0)] >= 0.5f) out.push_back(y * width + x);
  return out;
}

Raster placePicture(const Raster& picture, const CanvasMap& map, const Eigen::Vector2d& centre_m, double width_m,
                    double max_height_m) {
  Raster out(map.size_px, map.size_px);
  if (picture.width <= 0 || picture.height <= 0) return out;
  double w = width_m * map.px_per_m, h = w * picture.height / picture.width;
  if (h > max_height_m * map.px_per_m) {
    h = max_height_m * map.px_per_m;
    w = h * picture.width / picture.height;
  }
  const Eigen::Vector2d c = map.toPx(centre_m);
  io::CairoImage pic = io::CairoImage::fromCoverage(picture.width, picture.height, picture.ink);
  io::CairoImage canvas(map.size_px, map.size_px, io::PixelFormat::grey8);
  cairo_t* cr = canvas.cr();
  cairo_translate(cr, c.x() - w / 2, c.y() - h / 2);
  cairo_scale(cr, w / picture.width, h / picture.height);
  cairo_set_source_surface(cr, pic.surface(), 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_BILINEAR);
  cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_NONE);
  cairo_paint(cr);
  out.ink = canvas.coverage();
  return out;
}

}  // namespace creaturelab::charlotte
