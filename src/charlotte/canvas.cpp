#include "charlotte/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

void forEachLinePixel(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px,
                      const std::function<void(int, int, bool)>& f) {
  const Eigen::Vector2d d = b_px - a_px;
  const bool major_is_x = std::fabs(d.x()) >= std::fabs(d.y());
  const int m = major_is_x ? 0 : 1, n = 1 - m;
  // Walk the major axis from the end with the smaller coordinate, so a-b and b-a give the same pixels.
  const Eigen::Vector2d p = a_px[m] <= b_px[m] ? a_px : b_px, q = a_px[m] <= b_px[m] ? b_px : a_px;
  const int i0 = int(std::floor(p[m])), i1 = int(std::floor(q[m]));
  const double span = q[m] - p[m];
  for (int i = i0; i <= i1; ++i) {
    const double t = span > 0 ? std::clamp((i + 0.5 - p[m]) / span, 0.0, 1.0) : 0.0;
    const int j = int(std::floor(p[n] + t * (q[n] - p[n])));
    if (major_is_x) f(i, j, true);
    else f(j, i, false);
  }
}

void forEachBandPixel(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px, int band_px, int width, int height,
                      const std::function<void(int, int)>& f) {
  const int half = (band_px - 1) / 2;
  forEachLinePixel(a_px, b_px, [&](int x, int y, bool major_is_x) {
    // Pixels across the line: along y for a shallow line, along x for a steep one. Consecutive line
    // pixels differ in the major coordinate, so no pixel is visited twice.
    for (int k = -half; k <= half; ++k) {
      const int u = major_is_x ? x : x + k, v = major_is_x ? y + k : y;
      if (u >= 0 && v >= 0 && u < width && v < height) f(u, v);
    }
  });
}

void drawLine(Raster& r, const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px, float ink) {
  forEachLinePixel(a_px, b_px, [&](int x, int y, bool) {
    if (r.contains(x, y)) r.at(x, y) = std::max(r.at(x, y), ink);
  });
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
  const double x0 = c.x() - w / 2, y0 = c.y() - h / 2;
  const int px0 = std::max(0, int(std::floor(x0))), px1 = std::min(map.size_px - 1, int(std::floor(x0 + w)));
  const int py0 = std::max(0, int(std::floor(y0))), py1 = std::min(map.size_px - 1, int(std::floor(y0 + h)));
  constexpr int kSub = 4;
  for (int y = py0; y <= py1; ++y)
    for (int x = px0; x <= px1; ++x) {
      double sum = 0;
      for (int sy = 0; sy < kSub; ++sy)
        for (int sx = 0; sx < kSub; ++sx) {
          const double u = (x + (sx + 0.5) / kSub - x0) / w * picture.width;
          const double v = (y + (sy + 0.5) / kSub - y0) / h * picture.height;
          if (u >= 0 && v >= 0 && u < picture.width && v < picture.height) sum += picture.at(int(u), int(v));
        }
      out.at(x, y) = float(sum / (kSub * kSub));
    }
  return out;
}

}  // namespace creaturelab::charlotte
