#pragma once
// Dilation, thesis §6 (Figs. 6.7-6.8): "Dilation is a morphological operator ... In our
// implementation, we used a 7x7 structuring element. The basic effect of dilation is to enlarge the
// boundaries of orb web strands and of the dark region in the target image."
#include "charlotte/raster.hpp"

namespace creaturelab::charlotte {

// Grey-level dilation by a flat size x size square: out(x, y) = max of `in` over the square centred
// on (x, y) (for an even size the extra row and column lie below and right), clipped at the border.
// A flat square is separable, so this is a max over rows then over columns: O(pixels * size).
// size must be >= 1 (1 returns the input).
Raster dilate(const Raster& in, int size);

}  // namespace creaturelab::charlotte
