#pragma once
// The canvas the web is captured on (thesis §6: "we first capture the current orb web image from the
// screen to obtain the source image"), 600 x 600 pixels as every image of the thesis (§5.3.1: "the
// standard canvas size in all these images was kept constant at 600 by 600 pixels"), and the pixel
// sets the procedure works on: the capture of the strands, a strand's five-pixel neighbourhood
// (§6, Fig. 6.2) and a picture placed on the canvas. All drawn by cairo (io/cairo_image.hpp).
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "charlotte/raster.hpp"
#include "springs/network.hpp"

namespace creaturelab::charlotte {

// Web (x right, y up, metres) to canvas pixels (x right, y down; pixel (i, j) covers [i, i+1) x
// [j, j+1), its centre at (i + 1/2, j + 1/2)). Square pixels.
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

using LinePx = std::pair<Eigen::Vector2d, Eigen::Vector2d>;  // ends in canvas pixels

// The capture (§6): the lines stroked width_px wide, not anti-aliased, as a screen grab of the
// thesis's one-pixel OpenGL lines is: a pixel is ink 1 when its centre lies inside some stroke
// (butt ends), else 0. Binary on purpose: dilation then grows every strand to a full-ink 7 x 7 band,
// which is what the score's ratio assumes (score.hpp). Deterministic.
Raster captureLines(int width, int height, const std::vector<LinePx>& lines, double width_px = 1.0);

// The neighbourhood of a segment (§6): "a rectangular region, five pixels wide (including the single
// pixel width of the spiral segment itself), running along the length of the spiral line segment":
// the pixels whose centres lie inside the band_px-wide rectangle on a-b (no end caps), clipped to the
// width x height canvas. Returned as row-major pixel indices y * width + x, ascending, each once;
// the same for a-b and b-a. band_px >= 1.
std::vector<int> bandPixels(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px, int band_px, int width,
                            int height);

// Places a picture (a target image, one raster pixel per picture pixel) on a canvas of size_px:
// centred on centre_m, width_m wide, the height following the picture's aspect ratio but at most
// max_height_m (the width shrinks to keep the aspect then). Scaled by cairo with bilinear
// filtering, so edges are anti-aliased.
Raster placePicture(const Raster& picture, const CanvasMap& map, const Eigen::Vector2d& centre_m, double width_m,
                    double max_height_m);

}  // namespace creaturelab::charlotte
