#pragma once
// The canvas the web is captured on (thesis §6: "we first capture the current orb web image from the
// screen to obtain the source image"), 600 x 600 pixels as every image of the thesis (§5.3.1: "the
// standard canvas size in all these images was kept constant at 600 by 600 pixels"), and the pixel
// geometry of a strand: its one-pixel line and its five-pixel neighbourhood (§6, Fig. 6.2).
#include <functional>

#include <Eigen/Core>

#include "charlotte/raster.hpp"
#include "springs/network.hpp"

namespace creaturelab::charlotte {

// Web (x right, y up, metres) to canvas pixels (x right, y down; pixel (i, j) covers [i, i+1) x
// [j, j+1)). Square pixels.
struct CanvasMap {
  int size_px = 600;
  double left_m = 0, top_m = 0;  // web coordinates of the canvas's top-left corner
  double px_per_m = 1;

  Eigen::Vector2d toPx(const Eigen::Vector2d& x_m) const {
    return {(x_m.x() - left_m) * px_per_m, (top_m - x_m.y()) * px_per_m};
  }
  Eigen::Vector2d toM(const Eigen::Vector2d& p_px) const {
    return {left_m + p_px.x() / px_per_m, top_m - p_px.y() / px_per_m};
  }
};

// The canvas mapped onto the web: the square around the bounding box of every particle (x, y),
// centred on it, its side the box's larger side times (1 + 2 margin_fraction).
CanvasMap canvasOver(const springs::Points<3>& x_m, int size_px, double margin_fraction = 0.02);

// The pixels of the one-pixel-wide line from a to b (canvas pixels, continuous coordinates): one pixel
// per column (or per row when the line is steeper than 45 degrees), the one the line crosses at that
// column's centre. Calls f(x, y, major_is_x) for each, also those off the canvas. Deterministic.
void forEachLinePixel(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px,
                      const std::function<void(int x, int y, bool major_is_x)>& f);

// The neighbourhood of a segment (§6): "a rectangular region, five pixels wide (including the single
// pixel width of the spiral segment itself), running along the length of the spiral line segment":
// each line pixel and the (band_px - 1) / 2 pixels either side of it across the line. Pixels off the
// canvas are left out; each pixel is visited once. band_px odd >= 1.
void forEachBandPixel(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px, int band_px, int width, int height,
                      const std::function<void(int x, int y)>& f);

// Draws the line a-b into r with the given ink (max with what is there).
void drawLine(Raster& r, const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px, float ink = 1.0f);

// Places a picture (text or image, one raster pixel per picture pixel) on a canvas of size_px:
// centred on centre_m, width_m wide, the height following the picture's aspect ratio but at most
// max_height_m (the width shrinks to keep the aspect then). Each canvas pixel gets the mean ink of
// 4 x 4 samples (nearest picture pixel each), so edges are anti-aliased and the result does not
// depend on anything but these numbers.
Raster placePicture(const Raster& picture, const CanvasMap& map, const Eigen::Vector2d& centre_m, double width_m,
                    double max_height_m);

}  // namespace creaturelab::charlotte
