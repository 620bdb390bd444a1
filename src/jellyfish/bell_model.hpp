#pragma once
// The spring network of the jellyfish slice (Rudolf & Mould 2009, §3.2, Fig. 4): the
// subumbrellar surface as a chain of Hookean springs with angular springs at every interior
// point, a passive tentacle chain at each aperture point, and the circumferential muscle as
// springs across the bell between opposite points. Pure geometry and constants: no time, no fluid.
#include <string>
#include <vector>

#include "fluid/array2.hpp"
#include "jellyfish/jellyfish_params.hpp"
#include "springs/network.hpp"

namespace creaturelab::jellyfish {

struct MuscleSpring {
  int a = 0, b = 0;              // marker indices (left side, right side)
  double relaxed_length_m = 0;   // rest length at factor 1: the drawn distance
  double arc_weight_m = 0;       // arc length of the muscle band this element carries
  double stiffness_n_per_m = 0;  // rest_length model, per metre of depth: E_m s w / ℓ
  double tension_max_n_per_m = 0;  // active_tension model, per metre of depth: T_max w
  double aperture_position = 0;  // 1 at the aperture, 0 at the apex (the stagger's coordinate)
  int order_from_aperture = 0;   // 0 for the aperture pair (Spencer's delay counts from here)
};

struct BellModel {
  // Chain springs and bends of bell and tentacles. Masses are nominal: immersed-boundary markers
  // are massless (Peskin 2002), the network is used for its forces and stiffness only.
  springs::Network<2> network;
  std::vector<fluid::Vec2> rest_positions_m;  // every marker, as drawn (bell centred at the origin)
  std::vector<MuscleSpring> muscles;
  int bell_markers = 0;                       // markers 0 .. bell_markers-1: left aperture → apex → right aperture
  int apex = 0;
  std::vector<int> tentacle_markers;          // the rest: the left chains root → tip, then the right ones
  std::vector<std::vector<int>> tentacle_chains;  // each chain's markers from its root (a bell marker) to its tip
  double tentacle_permeability_m = 0;         // Darcy permeability of the chains across them, m (BellParams)
  double tentacle_axial_permeability_m = 0;   // the same along them, m (BellParams)
  double aperture_width_m = 0;                // drawn distance between the two aperture markers
  double bell_area_m2 = 0;                    // slice area of the bell's flesh (arc length × thickness)
  double segment_m = 0;                       // drawn length of every bell (and tentacle) segment
  MuscleModel muscle_model = MuscleModel::rest_length;
};

/// Builds the bell with its apex on +y, centred on x = 0, aperture at y = 0.
/// Throws std::invalid_argument with validate()'s message for unusable parameters.
BellModel buildBell(const BellParams& params);

}  // namespace creaturelab::jellyfish
