#pragma once
// Stage 2 of the web: primary spokes, hub, secondary spokes (Mehla 2005
// §5.2, Fig. 5.10 steps 1-7 and 9-12, Figs. 5.9, 5.11, 5.12).
#include <vector>

#include "web/frame_stage.hpp"

namespace creaturelab::web {

struct SpokeLayout {
  std::vector<std::vector<int>> primary;  // primary spoke strands, segment-middle mass first
  Point2 hub_centre_m{0, 0};
  std::vector<int> hub;                   // ring masses (one per primary arm), then the hub strands' own masses
  // Radii, each from its inner-frame mass to its hub mass, in order of angle about hub_centre_m.
  std::vector<std::vector<int>> radii;
};

// The far end of the primary spoke from the segment-middle mass at from_m (a mass of the other
// segments; see WebParams::primary_spoke_end).
int primarySpokeEnd(const WebBuilder& web, const FrameLayout& frame, const std::vector<int>& segment,
                    const Point2& from_m);

// Fig. 5.10 steps 1-3: from the middle mass of each inner-frame segment to the mass "opposite" it
// (primarySpokeEnd). A spoke within primary_spoke_min_angle_rad of an earlier one is not laid.
std::vector<std::vector<int>> layPrimarySpokes(WebBuilder& web, const FrameLayout& frame);

// "The intersection of the primary radial spokes" (Fig. 5.10 step 4): their least-squares
// intersection, or the frame centre if that falls outside the inner frame (lines nearly parallel).
Point2 primaryIntersection(const WebBuilder& web, const FrameLayout& frame,
                           const std::vector<std::vector<int>>& primary);

// Fig. 5.10 steps 4-7: splits each primary spoke at its mass nearest the intersection into two arms,
// takes on each arm the mass nearest hub_radius_m from the intersection, and joins those masses in
// order of angle with hub strands. Fills hub and the primary arms' radii.
//
// Reading of the thesis: step 5 takes, on the next spoke, the mass "closest to mass_close_intersection".
// Taken literally on spokes that all cross near one point, each step lands nearer the intersection
// than the last and the hub shrinks to a knot within a few steps; taking every arm's mass at the same
// distance from the intersection gives the small polygon of Fig. 5.11.
void joinHub(WebBuilder& web, SpokeLayout& spokes);

// Fig. 5.10 steps 9-12: from every secondary_spoke_stride-th inner-frame mass to one of the
// hub_attach_choices closest hub masses whose spoke crosses no radius already laid (drawn from the
// seeded generator, §5.2: "connected randomly to the masses in the hub"). Frame masses that already end a primary spoke, and frame masses within
// secondary_spoke_min_angle_rad (seen from the hub) of a radius already laid, are skipped.
void laySecondarySpokes(WebBuilder& web, const FrameLayout& frame, SpokeLayout& spokes);

// All of Fig. 5.10 but step 8 (the inward frame force, see frame_forces.hpp); radii sorted by angle.
SpokeLayout laySpokesAndHub(WebBuilder& web, const FrameLayout& frame);

}  // namespace creaturelab::web
