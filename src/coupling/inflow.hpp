#pragma once
// Fluid boundaries of the creature experiments that the fluid's wall types do not give (issue 16;
// Lentine et al. 2010 §4.3 Fig. 8, §7.1; seeds/creature-control-lentine-2010.txt):
//  - a steady uniform stream from the left (Fig. 8): the u faces of the first `stream_columns`
//    columns (the left wall's included) are set to the stream speed and the v faces of those cells
//    to zero before each advection, a Dirichlet inflow held over a band; with the right wall open
//    the stream leaves there. The paper does not say how its stream was made.
//  - a source at the floor (§7.1, "a source term at the floor forcing fluid flow upwards"): the
//    projection here cannot hold a mass source, so the floor is an open wall whose v faces and
//    those of the bottom `source_rows` rows are held at the source speed (an inflow through the
//    floor, the same flux); with the top open the injected fluid leaves there.
#include <string>

#include "fluid/fluid_params.hpp"
#include "fluid/mac_grid2.hpp"

namespace creaturelab::coupling {

struct InflowParams {
  double stream_m_per_s = 0.0;  // rightward stream speed (0: none)
  int stream_columns = 0;       // width of the inflow band, cells
  double source_m_per_s = 0.0;  // upward speed of the floor source (0: none)
  int source_rows = 0;          // height of the source band, cells
};

// "" when usable with these walls, else what is wrong.
std::string validate(const InflowParams& p, const fluid::FluidParams& fluid);

// The stage: sets the band velocities (no-op when both speeds are 0).
void applyInflow(fluid::MacGrid2& grid, const InflowParams& p);

// A uniform stream everywhere (the initial condition of Fig. 8; divergence free).
void fillStream(fluid::MacGrid2& grid, double stream_m_per_s);

}  // namespace creaturelab::coupling
