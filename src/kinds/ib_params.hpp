#pragma once
// What the immersed-boundary kinds (jellyfish, membrane) share: a fluid in a square free-slip box at a
// fixed coupled step, and the kernel's support radius in metres. The solver's structs describe their
// own fields (fluid::FluidParams, ib::CouplingParams); a kind composes them with its own defaults.
#include <string>

#include "fluid/fluid_params.hpp"
#include "ib/coupling.hpp"

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

}  // namespace creaturelab::kinds
