#pragma once
#include <cstdint>
#include <string>

#include "fluid/fluid_params.hpp"
#include "kinds/describe_kind.hpp"

namespace creaturelab::kinds {

// The fluid kind's parameters: the solver's own (fluid::FluidParams, whose in-class defaults are this
// kind's) in a square box, the step, the span and output, and the initial field.
struct FluidKindParams {
  fluid::FluidParams fluid;
  RealOrAuto dt_s;  // "auto": the CFL-adaptive policy
  double end_time_s = 1.0;
  double output_interval_s = 0.1;
  std::string initial = "rest";
  double amplitude_m_per_s = 1.0;
  double circulation_m2_per_s = 1e-3;
  double vortex_height_fraction = 0.6;
  std::int64_t tracers_per_side = 0;

  template <class V>
  void describe(V& v) {
    fluid.describeSquareBox(v);
    fluid.describeFluid(v);
    fluid.walls.describe(v);
    fluid.describeSchemes(v);
    v.realOrAuto("dt_s", dt_s, "s", 1e-9, 10, "fixed step, or \"auto\": CFL-adaptive with cfl_safety_factor and max_step_s");
    fluid.describeAdaptiveStep(v);
    v.real("end_time_s", end_time_s, "s", 1e-9, 1e6, "simulated time");
    v.real("output_interval_s", output_interval_s, "s", 1e-9, 1e6, "interval between stored fields and series samples");
    v.choice("initial", initial, {"rest", "taylor_green", "vortex_pair", "shear_layer"}, "initial velocity field");
    v.real("amplitude_m_per_s", amplitude_m_per_s, "m/s", 0, 1e3, "Taylor-Green amplitude, or the shear layer's speed");
    v.real("circulation_m2_per_s", circulation_m2_per_s, "m^2/s", 0, 1e3, "circulation of each vortex of the pair");
    v.real("vortex_height_fraction", vortex_height_fraction, "", 0, 1, "starting height of the pair, fraction of the box");
    fluid.describeBodyForce(v);
    v.integer("tracers_per_side", tracers_per_side, 0, 1000, "passive tracers on an n x n lattice (paper Fig. 6), 0 = none");
  }

  // The solver's parameters: the box made square, the step policy from dt_s.
  fluid::FluidParams solverParams() const;
  // Ranges, the solver's own validate(), then: an output interval within the run.
  std::string validate() const;
};

// The incompressible fluid alone (Rudolf & Mould 2009 §3.2, Eq. 1; Stam 1999 stable fluids on a
// MAC grid): decaying Taylor-Green vortices for convergence, a vortex pair meeting a wall, ...
class FluidKind : public DescribedKind<FluidKindParams> {
 public:
  FluidKind();
  std::string name() const override { return "fluid"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
