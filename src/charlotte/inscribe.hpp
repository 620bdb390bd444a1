#pragma once
// Inscribing a target (text or a bi-level image) into a settled orb web by removing spiral segments,
// Mehla 2005 ch. 6 (Figs. 6.1-6.4, 6.9-6.18). Deterministic, no I/O.
//
// The stages, each a function of its own (canvas.hpp, morphology.hpp, score.hpp, emphasis below):
//   1. segments    the web's spiral segments, mass on a spoke to mass on the next spoke   (Fig. 6.2)
//   2. candidates  cross-hatch only: two more strands from each segment's first mass      (Fig. 6.12)
//   3. capture     the settled web rasterised onto the canvas: the source image            (§6, Fig. 6.7)
//   4. dilate      source and target by a 7 x 7 structuring element                        (Figs. 6.7-6.8)
//   5. score       each segment's five-pixel band: floor(10 x intensity ratio)              (Fig. 6.9)
//   6. select      spiral segments scoring above the threshold (8) are removed; cross-hatch
//                  candidates are kept exactly where they match                             (Figs. 6.4, 6.12)
//   7. emphasis    outline: kept segments touching the letters; random attachments between
//                  masses inside the letters, from the seeded generator                     (Figs. 6.13-6.14)
// The caller then removes the selected springs (segments.hpp removeSprings) and settles the web again
// "so the web stays physically based" (§6: "the result of this process is an orb web which is still
// physically based").
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "charlotte/canvas.hpp"
#include "charlotte/raster.hpp"
#include "charlotte/segments.hpp"
#include "web/web_model.hpp"

namespace creaturelab::charlotte {

// The three ways of emphasising the letters of §6 (Figs. 6.12, 6.13, 6.14); none = Fig. 6.11.
enum class Emphasis : std::uint8_t { none, cross_hatch, random_attachments, strong_outline };

struct InscribeParams {
  int dilation_px = 7;   // §6: "we used a 7x7 structuring element"; odd, >= 1
  int band_px = 5;       // §6: neighbourhood "five pixels wide (including ... the spiral segment itself)"; odd
  int threshold = 8;     // §6: segments "with a score above a certain threshold score (set to 8 in our trials)"; 0..10
  Emphasis emphasis = Emphasis::none;
  // Cross-hatch (Fig. 6.12; the thesis does not say which "two more masses"): the masses this many
  // places inward and outward of the partner along its spoke. 1 = the neighbours, whose strands run
  // almost along the spiral (rings ~1 cm apart, segments 2-4 cm long); 2 crosses it at ~45 degrees.
  int crosshatch_reach = 2;
  // Random attachments (Fig. 6.13; the thesis gives no numbers): each spiral mass inside the letters
  // starts one with this probability, to a mass on another spoke inside the letters at most
  // attachment_max_length_m away, the strand's middle inside the letters too.
  double attachment_probability = 0.6;
  double attachment_max_length_m = 0.06;
  std::uint64_t seed = 1;  // random attachments: core::rng keyed by (seed, "charlotte.attachments", mass)

  // For the charlotte kind (kinds/describe.hpp), whose defaults these are; the seed is the web's.
  template <class V>
  void describe(V& v) {
    v.integer("dilation_px", dilation_px, 1, 99, "structuring element side, odd (§6: 7x7)");
    v.integer("band_px", band_px, 1, 99, "neighbourhood width of a segment, odd (§6: five pixels)");
    v.integer("threshold", threshold, 0, 10, "remove segments scoring above this (§6: 8)");
    v.choice("emphasis", emphasis,
             {{"none", Emphasis::none}, {"cross_hatch", Emphasis::cross_hatch},
              {"random_attachments", Emphasis::random_attachments}, {"strong_outline", Emphasis::strong_outline}},
             "emphasis of the letters (Figs. 6.11, 6.12, 6.13, 6.14)");
    v.integer("crosshatch_reach", crosshatch_reach, 1, 100,
              "cross-hatch: strands to the masses this many places in and out along the partner's spoke (Fig. 6.12)");
    v.real("attachment_probability", attachment_probability, "", 0, 1,
           "random attachments: chance a mass inside the letters starts one (Fig. 6.13; thesis gives none)");
    v.real("attachment_max_length_m", attachment_max_length_m, "m", 1e-4, 10, "random attachments: longest strand");
  }

  // "" or one sentence naming the first bad value.
  std::string validate() const;
};

struct Inscription {
  // The settled web plus every strand the emphasis laid (cross-hatch strands that matched, random
  // attachments), before anything is removed. Web particles and springs keep their indices.
  springs::Network<3> network;
  springs::State<3> state;
  std::vector<web::StrandType> type;  // new strands are spiral silk

  // Every segment: the web's spiral first (in spiralSegments order), then the laid extras.
  std::vector<Segment> segments;
  std::vector<int> score;             // per segment, 0..10; -1 for random attachments (not scored)
  std::vector<std::uint8_t> removed;  // per segment: taken out (spiral segments with score > threshold)
  std::vector<std::uint8_t> outline;  // per segment: drawn stronger (strong_outline)
  std::vector<std::uint8_t> inside;   // per segment: its middle lies on the (undilated) target
  std::vector<int> removed_springs;   // springs of the removed segments, ascending, indices into network

  Raster source, source_dilated, target_dilated;  // Figs. 6.7, 6.8 and the dilated Fig. 6.1
  int spiral_segments = 0;            // the web's own
  int crosshatch_candidates = 0;      // strands proposed (Fig. 6.12), scored against the target
  int crosshatch_kept = 0;            // those that matched and were laid
  int attachments = 0;                // random attachments laid (Fig. 6.13)
};

// `settled` is model's web at rest (same particles); `target` the target image on the canvas `map`
// (canvas-sized, ink 1 = target). `spiral` is how spiral silk is laid (web::strandSpec of the web's
// parameters) and mass_kg the mass of a new particle. Throws std::invalid_argument with
// params.validate()'s message.
Inscription inscribe(const web::WebModel& model, const springs::State<3>& settled, const CanvasMap& map,
                     const Raster& target, const web::StrandSpec& spiral, double mass_kg, const InscribeParams& params);

// --- stages, exposed for tests ------------------------------------------------------------------

// Stage 3: every spring of the network captured as a one-pixel line (canvas.hpp captureLines), plus the given extra lines
// between particles (the cross-hatch candidates: the web "modified by introducing additional strand
// segments", Fig. 6.12).
Raster captureSource(const springs::Network<3>& network, const springs::Points<3>& x_m, const CanvasMap& map,
                     const std::vector<std::pair<int, int>>& extra_lines = {});

// Stage 2 (Fig. 6.12): "These additional segments connect a particular mass to two more masses, in
// addition to the one mass to which it is currently connected": for each spiral segment a -> b, the
// strands from a to the spiral masses `reach` places inward and outward of b along b's spoke, unless
// already joined. radii as WebModel::spokes. Pairs in a deterministic order, each once.
std::vector<std::pair<int, int>> crossHatchPairs(const std::vector<std::vector<int>>& radii,
                                                 const std::vector<Segment>& spiral, int reach = 1);

// Stage 7 (Fig. 6.13): "random attachments between the masses within the letters". Masses: the ends
// of spiral segments whose pixel has target ink >= 0.5. Each (ascending index) starts a strand with
// probability p, to a partner drawn uniformly from the masses inside the letters on another spoke,
// within max_length_m, the strand's middle inside the letters, not yet joined. Draws are keyed by the
// mass index, so the result does not depend on the order of evaluation.
std::vector<std::pair<int, int>> randomAttachmentPairs(const std::vector<std::vector<int>>& radii,
                                                       const std::vector<Segment>& spiral,
                                                       const springs::Points<3>& x_m, const CanvasMap& map,
                                                       const Raster& target, const InscribeParams& params);

// Random gaps (Fig. 6.18: "we have introduced random gaps in the spiral"): a target of `count` discs
// of radius_m, centres uniform over the disc of region_radius_m around centre_m, drawn from the seeded
// generator (purpose "charlotte.random_gaps"); filled by cairo, anti-aliased.
Raster randomGapsTarget(const CanvasMap& map, const Eigen::Vector2d& centre_m, double region_radius_m, int count,
                        double radius_m, std::uint64_t seed);

}  // namespace creaturelab::charlotte
