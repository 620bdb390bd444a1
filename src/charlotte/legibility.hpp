#pragma once
// How readable the inscription is. The thesis judges by eye ("the text in figure 6.11, although
// visible with a little effort, is not easily readable", §6); these two numbers stand in for the eye.
//
// Shape: the region the web has lost, against the dilated target T. Omega = the dilated source of the
// web's own spiral at the settled positions (where there was spiral to lose), S = the dilated spiral
// silk of the final, re-settled web (every spiral spring, the emphasis's included), E = Omega minus S:
// it grows where the web, settling again, pulls the holes open, so the distortion counts against it.
// T = dilated target >= 0.5, counted only within Omega (no web can show a target where it has no
// spiral: the hub's free zone, beyond the frame):
//   iou = |E n T| / |E u (T n Omega)|,  precision = |E n T| / |E|,  recall = |E n T| / |T n Omega|.
// Contrast, on the final web: the density d of spiral silk (one-pixel lines) inside the letters
// (undilated target >= 0.5) and outside the dilated target, both within Omega:
//   contrast = (d_out - d_in) / (d_out + d_in),
// +1 when the letters are empty, 0 when they cannot be told from the web, negative when they are
// denser than the web around them (cross-hatch, attachments).
#include <vector>

#include "charlotte/canvas.hpp"
#include "charlotte/inscribe.hpp"

namespace creaturelab::charlotte {

struct Legibility {
  double iou = 0, precision = 0, recall = 0;
  double density_inside = 0, density_outside = 0, contrast = 0;
};

// `target` is the undilated target; `final_*` the re-settled web (any network whose spiral springs
// are typed spiral). The dilation is params.dilation_px.
Legibility measureLegibility(const Inscription& ins, const CanvasMap& map, const Raster& target,
                             const springs::Network<3>& final_network, const std::vector<web::StrandType>& final_type,
                             const springs::Points<3>& final_x_m, int dilation_px);

}  // namespace creaturelab::charlotte
