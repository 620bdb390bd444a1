#pragma once
// What the immersed-boundary kinds (jellyfish, membrane) share: a fluid in a square free-slip box at a
// fixed coupled step, and the kernel's support radius in metres. The solver's structs describe their
// own fields (fluid::FluidParams, ib::CouplingParams); a kind composes them with its own defaults.
#include <string>
#include <vector>

#include "fluid/fluid_params.hpp"
#include "ib/coupling.hpp"
#include "kinds/params.hpp"

namespace creaturelab::kinds {

// domain_m, cells, density_kg_per_m3, kinematic_viscosity_m2_per_s, advection, viscosity_scheme,
// fluid_threads: the fluid of a box a body is immersed in (fluid::FluidParams' own descriptions).
template <class V>
void describeFluidBox(V& v, fluid::FluidParams& f) {
  f.describeSquareBox(v);
  f.describeFluid(v);
  f.describeAdvection(v);
  f.describeViscosityScheme(v);
  f.describeThreads(v);
}

// kernel_radius_m: the kernel's support as a length, so that a grid study refines one body.
template <class V>
void describeKernelRadius(V& v, double& radius_m) {
  v.real("kernel_radius_m", radius_m, "m", 0, 10,
         "radius of the kernel's support; 0 = the grid's own (1 cell bilinear, 2 peskin4), else a whole multiple "
         "of that (ib/kernel.hpp)");
}

// The box made square (height and rows from the width and columns), stepped at the fixed dt_s: the
// coupled step is fixed, and a fluid running away is caught as a blow-up.
fluid::FluidParams fixedStepBox(fluid::FluidParams box, double dt_s);

// The kernel stretch that makes `kernel`'s support radius radius_m on a grid of cell dx_m: 1 for radius
// 0 and for a radius within one reach (a grid too coarse for it keeps its own kernel). Empty error, or a
// message naming radius_name when a larger radius is not a whole multiple of the kernel's reach in
// cells, or needs a stencil wider than kMaxStencilFaces.
struct KernelScale {
  int scale = 1;
  std::string error;
};
KernelScale kernelScale(ib::Kernel kernel, double radius_m, double dx_m,
                        const std::string& radius_name = "kernel_radius_m");

// --- Read by name, until the jellyfish and control_fluid kinds compose the described structs above.

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

// kernelScale above for the radius parameter radius_param (default kernel_radius_m), the kernel and
// the grid read by name.
KernelScale kernelScale(const ParamReader& r);
KernelScale kernelScale(const ParamReader& r, const std::string& radius_param);

ib::CouplingParams couplingParams(const ParamReader& r);

}  // namespace creaturelab::kinds
