#pragma once
// Grey-level images of the Charlotte's-web procedure (Mehla 2005 ch. 6):
// the target image (Fig. 6.1), the source image captured from the web (Fig. 6.2), and their
// dilations (Figs. 6.7-6.8). Values are "ink": 0 = empty background, 1 = a strand or the dark part of
// the target, so dilation (a max filter) grows the strands and the letters as in Fig. 6.8.
#include <cstddef>
#include <vector>

namespace creaturelab::charlotte {

struct Raster {
  int width = 0, height = 0;
  std::vector<float> ink;  // row-major, row 0 at the top; in [0, 1]

  Raster() = default;
  Raster(int w, int h) : width(w), height(h), ink(std::size_t(w) * std::size_t(h), 0.0f) {}
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  float& at(int x, int y) { return ink[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
  float at(int x, int y) const { return ink[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
  double sum() const {
    double s = 0;
    for (float v : ink) s += v;
    return s;
  }
};

}  // namespace creaturelab::charlotte
