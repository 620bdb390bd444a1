#include "charlotte/score.hpp"

#include <algorithm>
#include <cmath>

#include "charlotte/canvas.hpp"

namespace creaturelab::charlotte {

SegmentScore scoreSegment(const Raster& source_dilated, const Raster& target_dilated, const Eigen::Vector2d& a_px,
                          const Eigen::Vector2d& b_px, int band_px) {
  SegmentScore s;
  for (int i : bandPixels(a_px, b_px, band_px, source_dilated.width, source_dilated.height)) {
    s.source_total += source_dilated.ink[std::size_t(i)];
    s.target_total += target_dilated.ink[std::size_t(i)];
    ++s.band_pixels;
  }
  if (s.source_total > 0) {
    // A tiny tolerance so that a full overlap (ratio exactly 1 in exact arithmetic) scores 10, not 9.
    const double ratio = s.target_total / s.source_total;
    s.score = std::clamp(int(std::floor(10.0 * ratio + 1e-9)), 0, 10);
  }
  return s;
}

}  // namespace creaturelab::charlotte
