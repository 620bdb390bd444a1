#pragma once
// Renders of the web for the run folder (thesis Figs. 6.3, 6.4, 6.10-6.18), drawn by cairo:
// anti-aliased strands with alpha on a background. Per-strand grey and width are the caller's; the
// thesis shades its webs in greys (§5.3.8, Fig. 5.44) and draws the emphasis strands "darker than
// the rest" (Fig. 6.13).
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "charlotte/raster.hpp"
#include "io/cairo_image.hpp"

namespace creaturelab::charlotte {

using Rgb = std::array<float, 3>;  // each 0..1

class Painter {
 public:
  Painter(int width, int height, const Rgb& background);

  // Tints every pixel towards colour by alpha x ink (a target or an emptied region under the web).
  void wash(const Raster& ink, const Rgb& colour, float alpha);
  // A line width_px wide from a to b (pixel coordinates, round ends), anti-aliased, blended over
  // what is there with the given alpha.
  void line(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px, float width_px, const Rgb& colour, float alpha);

  std::vector<std::uint8_t> rgb();  // 8 bits per channel, row-major (for tests)
  std::vector<std::uint8_t> png();  // the image as PNG file bytes

 private:
  io::CairoImage image_;
};

}  // namespace creaturelab::charlotte
