#pragma once
// The six kinds of strand of the orb web (Mehla 2005 §5.2, Figs. 5.5-5.16),
// recorded per spring so sweeps and figures can treat them apart.
#include <array>
#include <cstdint>
#include <string_view>

namespace creaturelab::web {

enum class StrandType : std::uint8_t {
  outer_frame,      // attachment point -> inner-frame corner (Fig. 5.5 steps 6-8)
  inner_frame,      // between consecutive inner-frame corners (Fig. 5.5 steps 9-10)
  primary_spoke,    // inner-frame segment middle -> farthest frame mass (Fig. 5.10 steps 1-3)
  hub,              // ring joining the primary spokes near their intersection (Fig. 5.10 steps 4-7)
  secondary_spoke,  // inner-frame mass -> closest hub mass (Fig. 5.10 steps 9-12)
  spiral,           // initial and processed spiral (Figs. 5.15, 5.16)
};

inline constexpr int kStrandTypeCount = 6;

inline constexpr std::array<StrandType, kStrandTypeCount> kAllStrandTypes = {
    StrandType::outer_frame, StrandType::inner_frame,     StrandType::primary_spoke,
    StrandType::hub,         StrandType::secondary_spoke, StrandType::spiral};

// "outer_frame", "inner_frame", "primary_spoke", "hub", "secondary_spoke", "spiral".
constexpr std::string_view strandTypeName(StrandType t) {
  switch (t) {
    case StrandType::outer_frame: return "outer_frame";
    case StrandType::inner_frame: return "inner_frame";
    case StrandType::primary_spoke: return "primary_spoke";
    case StrandType::hub: return "hub";
    case StrandType::secondary_spoke: return "secondary_spoke";
    case StrandType::spiral: return "spiral";
  }
  return "?";
}

}  // namespace creaturelab::web
