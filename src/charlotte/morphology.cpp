#include "charlotte/morphology.hpp"

#include <algorithm>
#include <stdexcept>

namespace creaturelab::charlotte {

Raster dilate(const Raster& in, int size) {
  if (size < 1) throw std::invalid_argument("dilate: the structuring element must be at least 1 x 1");
  const int lo = (size - 1) / 2, hi = size / 2;  // reach left/up and right/down
  Raster rows(in.width, in.height), out(in.width, in.height);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      float m = 0;
      for (int u = std::max(0, x - lo); u <= std::min(in.width - 1, x + hi); ++u) m = std::max(m, in.at(u, y));
      rows.at(x, y) = m;
    }
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      float m = 0;
      for (int v = std::max(0, y - lo); v <= std::min(in.height - 1, y + hi); ++v) m = std::max(m, rows.at(x, v));
      out.at(x, y) = m;
    }
  return out;
}

}  // namespace creaturelab::charlotte
