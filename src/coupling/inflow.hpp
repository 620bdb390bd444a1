#pragma once
// Fluid boundaries of the creature experiments (Lentine et al. 2010 §4.3 Fig. 8, §7.1;
// "Creature Control in a Fluid Environment"). The paper says neither how its stream was made nor how
// its source was. Two ways here:
//  - an inflow wall (fluid::WallType::inflow, boundary2.hpp): the left wall or the floor is a
//    wall through which fluid enters at the stream or source speed, kept by the projection, so the
//    flux is exact at any step. The floor source's default since the band below lost flux.
//  - a held band: the normal faces of the first `stream_columns` columns (left wall included) or
//    `source_rows` rows (floor included) are set to the speed, and the stream band's tangential
//    faces to zero, before and after each stage, with the wall open. The projection then moves the
//    band again (p = 0 on the open wall), so the stream it drives falls short of the speed by an
//    amount that shrinks with the step and the band's depth (studies/control/flyer_convergence.toml). Kept for
//    block_flow's stream (Fig. 8), whose force settles in the step, and for comparison.
// With the right wall or the top open, the fluid leaves there.
#include <string>

#include "fluid/fluid_params.hpp"
#include "fluid/mac_grid2.hpp"

namespace creaturelab::coupling {

struct InflowParams {
  double stream_m_per_s = 0.0;  // rightward stream speed (0: none)
  int stream_columns = 0;       // width of the held band, cells (0: none, with an inflow left wall)
  double source_m_per_s = 0.0;  // upward speed of the floor source (0: none)
  int source_rows = 0;          // height of the held band, cells (0: none, with an inflow floor)

  // "" when usable with these walls, else what is wrong.
  std::string validate(const fluid::FluidParams& fluid) const;
};

// The stage: sets the held bands' velocities (no-op without bands).
void applyInflow(fluid::MacGrid2& grid, const InflowParams& p);

// A uniform stream everywhere (the initial condition of Fig. 8; divergence free).
void fillStream(fluid::MacGrid2& grid, double stream_m_per_s);

}  // namespace creaturelab::coupling
