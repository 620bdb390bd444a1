#pragma once
// Orb-web construction, Mehla 2005 §5.2 (pseudo-code Figs. 5.5, 5.10,
// 5.15, 5.16). Deterministic: the same parameters give the same web, bit for bit; the only random
// choices (hub attachment of secondary spokes, spiral jitter) come from core::rng keyed by params.seed.
#include "springs/system.hpp"
#include "web/web_model.hpp"
#include "web/web_params.hpp"

namespace creaturelab::web {

// The stages, in order (each in its own file):
//   1. frame        centre, inner-frame corners, outer frame, inner frame (Fig. 5.5)      frame_stage
//   2. spokes       primary spokes, hub, secondary spokes (Fig. 5.10 steps 1-7, 9-12)      spoke_stage
//   3. spiral       initial spiral (Fig. 5.15), processed spiral (Fig. 5.16)              spiral_stage
//   4. forces       inward radial force on the inner frame (Fig. 5.8, Fig. 5.10 step 8)     frame_forces
// Throws std::invalid_argument with params.validate()'s message when the parameters are bad.
WebModel build(const WebParams& params);

}  // namespace creaturelab::web
