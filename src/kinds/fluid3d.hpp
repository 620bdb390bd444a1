#pragma once
#include <cstdint>
#include <string>

#include "fluid3d/fluid_params3.hpp"
#include "kinds/describe_kind.hpp"

namespace creaturelab::kinds {

// The fluid3d kind's parameters: the 3-D solver's own (fluid3d::FluidParams3, whose in-class defaults
// are this kind's), the step, the span and output, the initial field and the stored plane or volume.
struct Fluid3dKindParams {
  fluid3d::FluidParams3 fluid;
  std::int64_t cells = 0;  // > 0: cells_x, and cells_y, cells_z from the box's proportions
  RealOrAuto dt_s;  // "auto": the CFL-adaptive policy
  double end_time_s = 1.0;
  double output_interval_s = 0.1;
  std::string initial = "rest";
  double amplitude_m_per_s = 1.0;
  std::string slice_normal = "y";
  std::string stored_fields = "plane";

  template <class V>
  void describe(V& v) {
    fluid.describe(v);
    v.integer("cells", cells, 0, 1024,
              "cells along x, with cells_y and cells_z following the box's proportions (cubic cells), for grid "
              "refinement; 0: cells_x, cells_y, cells_z as given");
    v.realOrAuto("dt_s", dt_s, "s", 1e-9, 10, "fixed step, or \"auto\": CFL-adaptive with cfl_safety_factor and max_step_s");
    v.real("end_time_s", end_time_s, "s", 1e-9, 1e6, "simulated time");
    v.real("output_interval_s", output_interval_s, "s", 1e-9, 1e6, "interval between series samples and stored planes");
    v.choice("initial", initial, {"rest", "taylor_green", "abc"},
             "initial velocity: rest, the Taylor-Green vortex (Taylor & Green 1937) or the ABC flow (Dombre et al. "
             "1986), one wavelength across a cubic box, compared with their exact decay");
    v.real("amplitude_m_per_s", amplitude_m_per_s, "m/s", 0, 1e3,
           "Taylor-Green amplitude A, or the ABC flow's A (B = 0.8 A, C = 0.6 A)");
    v.choice("slice_normal", slice_normal, {"x", "y", "z"},
             "axis normal to the stored plane of fields, through the box's centre cell layer");
    v.choice("stored_fields", stored_fields, {"plane", "volume"},
             "fields stored per output frame, cell-centred u, v, w, pressure, |vorticity| and Q: the plane of "
             "slice_normal (frames, rows, columns), or the whole box (frames, nz, ny, nx: 48 B per cell and frame)");
  }

  // The solver's parameters: the grid from cells, the step policy from dt_s.
  fluid3d::FluidParams3 solverParams() const;
  // Ranges, the solver's own validate(), then: an output interval within the run; a Taylor-Green or
  // ABC start in a cubic box whose sides are periodic (or free-slip, for Taylor-Green).
  std::string validate() const;
};

// The 3-D incompressible fluid alone (Lentine, Grafe & Fedkiw 2010 §4.1, Eqs. 5-8; Stam 1999 stable
// fluids on a MAC grid): decaying Taylor-Green and ABC flows for convergence, an updraft from an
// inflow floor through an open top (their §7.1), with vorticity and Q on a plane or in the whole box.
class Fluid3dKind : public DescribedKind<Fluid3dKindParams> {
 public:
  Fluid3dKind();
  std::string name() const override { return "fluid3d"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
