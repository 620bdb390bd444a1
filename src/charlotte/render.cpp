#include "charlotte/render.hpp"

#include <algorithm>
#include <cmath>

namespace creaturelab::charlotte {

Painter::Painter(int width, int height, const Rgb& background)
    : width_(width), height_(height), rgb_(std::size_t(width) * std::size_t(height) * 3) {
  for (std::size_t i = 0; i < rgb_.size(); ++i) rgb_[i] = background[i % 3];
}

void Painter::wash(const Raster& ink, const Rgb& colour, float alpha) {
  for (int y = 0; y < std::min(height_, ink.height); ++y)
    for (int x = 0; x < std::min(width_, ink.width); ++x) {
      const float a = alpha * ink.at(x, y);
      float* c = &rgb_[(std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3];
      for (int k = 0; k < 3; ++k) c[k] = c[k] * (1 - a) + colour[k] * a;
    }
}

void Painter::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, float width_px, const Rgb& colour, float alpha) {
  const double reach = width_px / 2.0 + 1.0;
  const int x0 = std::max(0, int(std::floor(std::min(a.x(), b.x()) - reach)));
  const int x1 = std::min(width_ - 1, int(std::floor(std::max(a.x(), b.x()) + reach)));
  const int y0 = std::max(0, int(std::floor(std::min(a.y(), b.y()) - reach)));
  const int y1 = std::min(height_ - 1, int(std::floor(std::max(a.y(), b.y()) + reach)));
  const Eigen::Vector2d d = b - a;
  const double len2 = d.squaredNorm();
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d c(x + 0.5, y + 0.5);
      const double t = len2 > 0 ? std::clamp((c - a).dot(d) / len2, 0.0, 1.0) : 0.0;
      const double dist = (c - (a + t * d)).norm();
      const double cover = std::clamp(width_px / 2.0 + 0.5 - dist, 0.0, 1.0);
      if (cover <= 0) continue;
      const float w = alpha * float(cover);
      float* p = &rgb_[(std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3];
      for (int k = 0; k < 3; ++k) p[k] = p[k] * (1 - w) + colour[k] * w;
    }
}

RgbImage Painter::image() const {
  RgbImage out(width_, height_, 0);
  for (std::size_t i = 0; i < rgb_.size(); ++i)
    out.rgb[i] = std::uint8_t(std::lround(std::clamp(rgb_[i], 0.0f, 1.0f) * 255.0f));
  return out;
}

}  // namespace creaturelab::charlotte
