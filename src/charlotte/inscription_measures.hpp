#pragma once
// What an inscription did and how legible it left the web (A. Mehla, Modeling and Animation of Orb
// Webs, MSc thesis 2005, §6): the segments removed and where, the target's share of the canvas, the
// legibility just after the cut and after the web settled again (legibility.hpp), and which segment
// each spring belongs to.
#include <cstdint>
#include <vector>

#include "charlotte/inscribe.hpp"
#include "charlotte/legibility.hpp"

namespace creaturelab::charlotte {

struct InscriptionMeasures {
  int segments_removed = 0;
  int removed_inside_target = 0;  // removed segments whose middle lies on the undilated target
  int outline_segments = 0;       // segments drawn stronger (strong_outline)
  double target_area_fraction = 0;  // dilated target pixels / canvas pixels
  Legibility settled;             // after the web settled again (final_x_m)
  Legibility cut;                 // just after the cut (pruned.state)
};

InscriptionMeasures measureInscription(const Inscription& ins, const CanvasMap& map, const Raster& target,
                                       const Pruned& pruned, const springs::Points<3>& final_x_m, int dilation_px);

// Per spring of ins.network the segment it belongs to, -1 for none.
std::vector<std::int64_t> springSegments(const Inscription& ins);

}  // namespace creaturelab::charlotte
