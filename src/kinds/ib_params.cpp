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

KernelScale kernelScale(const ParamReader& r) { return kernelScale(r, "kernel_radius_m"); }

KernelScale kernelScale(const ParamReader& r, const std::string& radius_param) {
  return kernelScale(*ib::parseKernel(r.text("kernel")), r.real(radius_param),
                     r.real("domain_m") / double(r.integer("cells")), radius_param);
}

ParamSpec viscositySchemeSpec() {
  return choice("viscosity_scheme", "backward_euler", {"backward_euler", "crank_nicolson"},
                "viscous term in time: backward Euler (Stam 1999 §2.2, first order) or Crank-Nicolson (second order "
                "for that stage alone)");
}

std::vector<ParamSpec> fluidBoxSpecs(const FluidBoxDefaults& d) {
  return {
      real("domain_m", d.domain_m, "m", 1e-3, 100, d.domain_doc),
      integer("cells", d.cells, 8, 2048, d.cells_doc),
      real("density_kg_per_m3", 1000.0, "kg/m^3", 1e-3, 1e6, d.density_doc),
      real("kinematic_viscosity_m2_per_s", d.kinematic_viscosity_m2_per_s, "m^2/s", 0, 10, d.viscosity_doc),
      choice("advection", d.advection, {"semi_lagrangian", "maccormack", "upwind2_rk2"}, d.advection_doc),
      viscositySchemeSpec(),
      integer("fluid_threads", 1, 1, 16,
              "threads inside each fluid step; results are bitwise the same for any count (fluid/worker_pool.hpp); "
              "helps only on idle cores"),
  };
}

std::vector<ParamSpec> couplingSpecs(const CouplingDefaults& d) {
  return {
      choice("kernel", d.kernel, {"bilinear", "peskin4"}, d.kernel_doc),
      real("kernel_radius_m", d.kernel_radius_m, "m", 0, 10, d.kernel_radius_doc),
      boolean("semi_implicit", true, "linearised implicit elastic forces (ib/coupling.hpp); false = explicit Peskin"),
      choice("implicit_mobility", "stencil", {"stencil", "local_mass"}, d.mobility_doc),
      real("implicit_mass_factor", 1.0, "", 1e-6, 100, "local_mass only: added mass per marker in rho dx^2"),
      real("implicit_theta", d.implicit_theta, "", 0.5, 1.0,
           "semi-implicit only: elastic force at X^n + theta dt U* (ib/coupling.hpp); 1 = backward Euler, which damps "
           "the recoil; 0.5 = the step's middle" +
               (d.implicit_theta_doc.empty() ? std::string() : ". " + d.implicit_theta_doc)),
      real("implicit_reuse_tolerance", 1e-8, "", 0, 1e-4,
           "banded solve (>= 300 markers): relative residual accepted when refining on earlier LU factors, else "
           "refactored (ib/reused_banded_solve.hpp); 0 = every step"),
  };
}

fluid::FluidParams squareFluidParams(const ParamReader& r, double dt_s) {
  fluid::FluidParams f;  // free-slip walls, exact (fast direct) projection
  f.domain_width_m = f.domain_height_m = r.real("domain_m");
  f.cells_x = f.cells_y = int(r.integer("cells"));
  f.density_kg_per_m3 = r.real("density_kg_per_m3");
  f.kinematic_viscosity_m2_per_s = r.real("kinematic_viscosity_m2_per_s");
  f.advection = *fluid::parseAdvectionScheme(r.text("advection"));
  f.viscosity_scheme = *fluid::parseViscosityScheme(r.text("viscosity_scheme"));
  f.threads = int(r.integer("fluid_threads"));
  // The coupled step is fixed; a fluid running away is caught as a blow-up.
  f.time_step_policy = fluid::TimeStepPolicy::fixed;
  f.fixed_step_s = dt_s;
  f.blowup_speed_m_per_s = r.real("blowup_speed_m_per_s");
  return f;
}

fluid::FluidParams fluidBoxParams(const ParamReader& r) { return squareFluidParams(r, r.real("dt_s")); }

ib::CouplingParams couplingParams(const ParamReader& r) {
  ib::CouplingParams c;
  c.kernel = *ib::parseKernel(r.text("kernel"));
  c.kernel_scale = kernelScale(r).scale;
  c.semi_implicit = r.boolean("semi_implicit");
  c.mobility = *ib::parseImplicitMobility(r.text("implicit_mobility"));
  c.implicit_mass_factor = r.real("implicit_mass_factor");
  c.implicit_theta = r.real("implicit_theta");
  c.factor_reuse.tolerance = r.real("implicit_reuse_tolerance");
  return c;
}

}  // namespace creaturelab::kinds
