#pragma once
// The score of one spiral segment, thesis §6, Fig. 6.9:
//   1. intensity_ratio = total_source_intensity / total_target_intensity
//   2. thescore = floor(10 * intensity_ratio)
// where each total sums one dilated image over the segment's neighbourhood (a band five pixels wide
// along the segment, canvas.hpp). Segments scoring above the threshold (8 in the thesis's trials) are
// removed.
//
// Which way round. The text says the score "indicat[es] the degree of intensity match, ranging
// between 1 to 10", and that the segments removed (score > 8) are those "where there was an overlap of
// the target and the source images". With both images as ink (strands and the target's dark region
// are what dilation grows, Figs. 6.7-6.8), the dilated strand (7 x 7) always fills its own five-pixel
// band, so the source total is the band's pixel count and the literal source/target ratio would be 1
// on a full overlap and grow without bound where there is no target at all: every segment away from
// the letters would score far above 8 and be removed, the opposite of Fig. 6.4. The ratio that does
// range over 0..1 and reaches 1 on a full overlap is target/source: the share of the segment's
// dilated neighbourhood that the dilated target covers. That is what this computes; the score is
// clamped to 0..10 (a grey target darker than the strands could push it past 1).
#include <Eigen/Core>

#include "charlotte/raster.hpp"

namespace creaturelab::charlotte {

struct SegmentScore {
  double source_total = 0;  // sum of the dilated source over the band (ink x pixels)
  double target_total = 0;  // sum of the dilated target over the band
  int band_pixels = 0;
  int score = 0;            // floor(10 * target_total / source_total), in 0..10; 0 if source_total == 0
};

// Both rasters are the same size; a_px, b_px the segment's end masses on the canvas.
SegmentScore scoreSegment(const Raster& source_dilated, const Raster& target_dilated, const Eigen::Vector2d& a_px,
                          const Eigen::Vector2d& b_px, int band_px);

}  // namespace creaturelab::charlotte
