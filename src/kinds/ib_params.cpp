#include "kinds/ib_params.hpp"

#include <cmath>
#include <cstdio>

namespace creaturelab::kinds {

fluid::FluidParams fixedStepBox(fluid::FluidParams f, double dt_s) {
  f.makeSquare();
  f.time_step_policy = fluid::TimeStepPolicy::fixed;
  f.fixed_step_s = dt_s;
  return f;
}

KernelScale kernelScale(ib::Kernel kernel, double radius_m, double dx_m, const std::string& radius_name) {
  if (radius_m == 0) return {};
  const int reach_cells = ib::kernelSupportCells(kernel) / 2;
  const double scale = radius_m / (reach_cells * dx_m);
  // A grid too coarse for the radius keeps its own kernel (never narrower than the grid can
  // carry); the kernel_cells metric records the stretch each point ran with.
  if (scale <= 1.0 + 1e-6) return {};
  const long whole = std::lround(scale);
  const int largest = ib::kMaxStencilFaces / ib::kernelSupportCells(kernel);
  if (whole > largest || std::abs(scale - double(whole)) > 1e-6 * scale) {
    char msg[400];
    std::snprintf(msg, sizeof msg,
                  "%s = %g m must be a whole multiple (at most %d) of the %s kernel's reach of %d "
                  "cell(s) of %g m (domain_m / cells), or at most one reach; it is %.4g reaches: change "
                  "%s or cells",
                  radius_name.c_str(), radius_m, largest, std::string(ib::to_string(kernel)).c_str(), reach_cells,
                  dx_m, scale, radius_name.c_str());
    return {1, msg};
  }
  return {int(whole), ""};
}

}  // namespace creaturelab::kinds
