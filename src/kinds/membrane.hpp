#pragma once
#include <string>

#include "fluid/fluid_params.hpp"
#include "ib/coupling.hpp"
#include "ib/membrane_body.hpp"
#include "kinds/describe_kind.hpp"
#include "kinds/describe_notes.hpp"
#include "kinds/ib_params.hpp"

namespace creaturelab::kinds {

// The membrane kind's parameters: the coupling (ib::CouplingParams), the fluid in its square free-slip
// box (fluid::FluidParams), the membrane (ib::MembraneParams, whose in-class defaults are this kind's),
// the step and the output. The shared structs carry this test's defaults where they differ, each with
// its reason in the description.
struct MembraneKindParams {
  ib::CouplingParams coupling{.kernel = ib::Kernel::bilinear};
  double kernel_radius_m = 0.0;
  fluid::FluidParams fluid{.domain_width_m = 1.0,
                           .domain_height_m = 1.0,
                           .kinematic_viscosity_m2_per_s = 1e-2,
                           .blowup_speed_m_per_s = 10.0};
  ib::MembraneParams membrane;
  double dt_s = 0.01;
  double duration_s = 5.0;
  double frame_rate_hz = 10.0;

  template <class V>
  void describe(V& v) {
    // Where this test's defaults differ from the shared structs': why.
    DefaultNotes noted(v, {
        {"kernel", "the jellyfish paper's hat, which the kernels experiment sets beside Peskin's"},
        {"implicit_theta", "1, which the membrane test compares with 0.5"},
        {"domain_m", "1 m: a viscous liquid in a free-slip box, a test of the method, not of sea water"},
        {"cells", "100, the larger of the jellyfish paper's grids (50 and 100)"},
        {"kinematic_viscosity_m2_per_s", "1e-2 (10 000 x water) damps the relaxation within a few seconds"},
        {"blowup_speed_m_per_s", "10, about 200x the default relaxation flow"},
    });
    coupling.describe(noted);
    describeKernelRadius(v, kernel_radius_m);
    describeFluidBox(noted, fluid);
    membrane.describe(v);
    v.real("dt_s", dt_s, "s", 1e-7, 1, "coupled step (fixed)");
    v.real("duration_s", duration_s, "s", 1e-6, 1e6, "simulated time");
    fluid.describeBlowupSpeed(noted);
    v.real("frame_rate_hz", frame_rate_hz, "Hz", 1e-3, 1e4, "series and marker frames per second");
  }

  // The solver's structs: the box made square at the fixed step, the ellipse centred in it, the kernel
  // stretched to kernel_radius_m on the grid.
  fluid::FluidParams fluidParams() const;
  ib::MembraneParams membraneParams() const;
  ib::CouplingParams couplingParams() const;
  // Ranges, the structs' own validate(), the kernel's radius on the grid, then: the membrane 4 cells
  // from the walls, a step within the run, at most one frame per step.
  std::string validate() const;
};

// The immersed-boundary membrane test (ib/membrane_body.hpp; Peskin 2002): an elliptical ring of
// zero-rest-length springs in a box of fluid relaxes to the circle of the same area; the
// enclosed area it loses is the coupling's leakage (Rudolf & Mould 2009 §3.2, "a minimal amount
// of leakage across solid boundaries").
class MembraneKind : public DescribedKind<MembraneKindParams> {
 public:
  MembraneKind();
  std::string name() const override { return "membrane"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
};

}  // namespace creaturelab::kinds
