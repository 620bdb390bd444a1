#pragma once
// The parameters the immersed-boundary kinds (jellyfish, membrane) share: a fluid in a square
// free-slip box and its coupling to the markers (ib/coupling.hpp). Declared and read in one place
// so that the names a kind declares are the names it reads. Defaults and docs stay each kind's:
// the jellyfish cites its paper's figures, the membrane its own test of the method.
#include <string>
#include <vector>

#include "fluid/fluid_params.hpp"
#include "ib/coupling.hpp"
#include "kinds/params.hpp"

namespace creaturelab::kinds {

// What each kind says about its fluid box.
struct FluidBoxDefaults {
  double domain_m = 0;
  std::string domain_doc;
  std::string cells_doc;
  long cells = 100;
  std::string density_doc;
  double kinematic_viscosity_m2_per_s = 0;
  std::string viscosity_doc;
  std::string advection_doc;
  std::string advection = "semi_lagrangian";
};

// domain_m, cells, density_kg_per_m3, kinematic_viscosity_m2_per_s, advection, fluid_threads.
std::vector<ParamSpec> fluidBoxSpecs(const FluidBoxDefaults& defaults);
/// viscosity_scheme, which squareFluidParams reads: every kind that calls it declares this.
ParamSpec viscositySchemeSpec();

// What each kind says about the coupling.
struct CouplingDefaults {
  std::string kernel;  // "bilinear" | "peskin4"
  std::string kernel_doc;
  std::string mobility_doc;
  double kernel_radius_m = 0;  // 0: the grid's own kernel
  std::string kernel_radius_doc;
  double implicit_theta = 1.0;  // 1: backward Euler, ib::CouplingParams' own default
  std::string implicit_theta_doc;
};

// kernel, kernel_radius_m, semi_implicit, implicit_mobility, implicit_mass_factor, implicit_theta,
// implicit_reuse_tolerance.
std::vector<ParamSpec> couplingSpecs(const CouplingDefaults& defaults);

// The square box's fluid as read by every coupled kind (control_fluid too): domain_m, cells,
// density_kg_per_m3, kinematic_viscosity_m2_per_s, advection, fluid_threads, blowup_speed_m_per_s;
// a fixed step of dt_s. Walls stay the defaults (free slip) for the caller to set.
fluid::FluidParams squareFluidParams(const ParamReader& r, double dt_s);

// The box's fluid from fluidBoxSpecs' parameters, dt_s (the fixed step) and blowup_speed_m_per_s,
// which each kind declares itself: their ranges and defaults differ.
fluid::FluidParams fluidBoxParams(const ParamReader& r);

// The kernel stretch that makes the kernel's radius kernel_radius_m on this kind's grid (cell
// domain_m / cells): 1 for radius 0 and for a radius within one reach (a grid too coarse for it keeps
// its own kernel). Empty error, or a message naming the parameters when a larger radius is not a
// whole multiple of the kernel's reach in cells, or needs a stencil wider than kMaxStencilFaces.
struct KernelScale {
  int scale = 1;
  std::string error;
};
KernelScale kernelScale(const ParamReader& r);
// The same for another radius parameter (e.g. the jellyfish's tentacle_kernel_radius_m).
KernelScale kernelScale(const ParamReader& r, const std::string& radius_param);

ib::CouplingParams couplingParams(const ParamReader& r);

}  // namespace creaturelab::kinds
