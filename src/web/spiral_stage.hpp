#pragma once
// Stage 3 of the web: the spiral (Mehla 2005 §5.2, Figs. 5.13-5.16).
#include <vector>

#include "web/spoke_stage.hpp"

namespace creaturelab::web {

struct SpiralResult {
  int segments = 0;  // spiral strands laid
};

// Fig. 5.15 (initial spiral) then Fig. 5.16 (processed spiral), on the radii in angular order.
//
// A "walk" from a spoke mass goes once round the web: on each next radius it takes the candidate
// mass closest to the current one (Fig. 5.15: "next_mass <-- mass closest to initial_mass on next
// spoke"), lays a spiral strand to it unless those two masses are already joined, and moves on; the
// step after the last radius returns to the starting radius. Candidates: a radius's masses other than
// its inner-frame mass and its spiral_free_masses masses at the hub end (§5.2: "we end this process a
// little distance away from the hub"; see WebParams::spiral_free_masses), whose strand from the current
// mass keeps out of the free zone: the disc about the hub centre through the farthest of those hub-end
// masses on any radius.
// With probability spiral_jitter a step takes a neighbour (along the radius) of the closest candidate
// instead (§5.2: "a small amount of randomness"). A walk with no candidate on the next radius ends.
//
// Initial spiral: a walk from every candidate of the first radius, from the frame inward.
// Processed spiral: while some radius has more than spiral_density candidates no spiral strand touches
// ("uncovered"), walk from each uncovered candidate of the radius with the most of them (Fig. 5.16,
// max_spoke). Each round covers at least one more mass, so it ends.
SpiralResult laySpiral(WebBuilder& web, const SpokeLayout& spokes);

}  // namespace creaturelab::web
