#pragma once
// The web settling again after the cut (A. Mehla, Modeling and Animation of Orb Webs, MSc thesis
// 2005, §6: "the result of this process is an orb web which is still physically based"): the pruned
// network under the web's own masses' constant force (the inner frame's inward pull, Fig. 5.8), run
// with RK4 (§4.2, Eqs. 4.16-4.19) or solved for its static equilibrium, and how far the hub moves
// from where it was just after the cut.
#include <vector>

#include "charlotte/segments.hpp"
#include "web/web_model.hpp"

namespace creaturelab::charlotte {

struct ResettleParams {
  bool dynamic = true;            // RK4 in 0.02 s frames (§5.2.1 'time step'); else static equilibrium
  double time_s = 10;             // dynamic: how long
  double settling_fraction = 0;   // dynamic: settled when the kinetic energy stays below this fraction of its peak
};

struct Resettled {
  springs::State<3> state;             // at the end
  std::vector<double> hub_shift_m;     // per frame (static: one value): |hub - hub just after the cut|
  std::vector<double> time_s;          // per frame (static: {0}); empty until the run finished
  std::vector<double> kinetic_energy_j;  // dynamic only, per frame
  double settling_time_s;              // dynamic: when it settled (NaN if never or static)
  double iterations;                   // static: the equilibrium's iterations (NaN if dynamic)
  bool converged = false;              // static: the equilibrium converged (dynamic: true)
};

// Settles `pruned` (removeSprings of model's web and its emphasis) into `out`, which holds the
// frames recorded so far if the dynamic run diverges (springs::DivergenceError).
void resettle(const web::WebModel& model, const Pruned& pruned, const ResettleParams& p, Resettled& out);

}  // namespace creaturelab::charlotte
