#pragma once
// Stage 1 of the web: outer and inner frame (Mehla 2005 §5.2, Fig. 5.5).
#include <vector>

#include "web/web_builder.hpp"

namespace creaturelab::web {

struct FrameLayout {
  Point2 centre_m{0, 0};                  // Fig. 5.5 steps 2-4
  std::vector<int> attachment;            // pinned anchor particles, one per attachment point
  std::vector<int> corners;               // inner-frame corner particles (Fig. 5.4, "I")
  std::vector<std::vector<int>> segments; // segment i: corner i ... corner i+1, every mass in order
  std::vector<int> chain;                 // the closed inner frame, corner 0 first, each mass once
};

// Fig. 5.5: anchors (pinned, step 8), corners moved MOVE_OUTER toward the centre (step 5), outer-frame
// strands anchor -> corner (steps 6-7), inner-frame strands corner i -> corner i+1 (steps 9-10).
FrameLayout layFrame(WebBuilder& web);

}  // namespace creaturelab::web
