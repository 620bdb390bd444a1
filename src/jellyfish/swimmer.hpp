#pragma once
// A jellyfish swimming in a box of sea water: the bell (bell_model.hpp), its muscles
// (jellyfish_body.hpp), the fluid (fluid/fluid_solver2.hpp) and the immersed-boundary coupling
// (ib/coupling.hpp), stepped together at a fixed step (Rudolf & Mould 2009 §3.2). No I/O.
#include <memory>
#include <vector>

#include "fluid/fluid_solver2.hpp"
#include "ib/coupling.hpp"
#include "jellyfish/jellyfish_body.hpp"

namespace creaturelab::jellyfish {

// The jellyfish kind's fluid, the converged setting of the jellyfish convergence experiments (grid,
// step, scheme and box refined together): a 0.25 m by 0.36 m free-slip box of 1 mm cells, a fluid 38
// times as viscous as water, MacCormack advection, the bell's force after the advection, a fixed step.
fluid::FluidParams jellyfishFluid();
// Its coupling: Peskin's kernel stretched to the bell's 4 mm thickness on that grid (2 cells per
// kernel unit), the semi-implicit force at the step's middle (theta = 1/2).
ib::CouplingParams jellyfishCoupling();

struct SwimmerConfig {
  BellParams bell;
  ActivationParams activation;
  fluid::FluidParams fluid = jellyfishFluid();  // domain, grid, water, walls, advection
  ib::CouplingParams coupling = jellyfishCoupling();
  // The tentacle markers' own kernel stretch (ib::CouplingParams::marker_kernel_scales): filaments spread
  // narrower than the bell. 0: the bell's (coupling.kernel_scale).
  int tentacle_kernel_scale = 2;
  double dt_s = 0.00125;  // coupled step (see ib/coupling.hpp on stability); = fluid.fixed_step_s
  // Where the middle of the aperture starts, as fractions of the domain (apex toward +y).
  double start_x_fraction = 0.5;
  double start_y_fraction = 0.5;

  /// The fluid as the jellyfish kind offers it: domain_m and cells (a square box the kind stretches to
  /// its aspect), density_kg_per_m3, kinematic_viscosity_m2_per_s, advection, viscosity_scheme,
  /// fluid_threads (FluidParams' own fields, with this swimmer's defaults and reasons).
  template <class V>
  void describeFluid(V& v) {
    v.real("domain_m", fluid.domain_width_m, "m", 1e-3, 100,
           "width of the free-slip box (its height is box_aspect times it): 6.25 bell diameters, chosen close to "
           "the paper's 10-diameter box (§3.2) in distance per cycle");
    v.integer("cells", fluid.cells_x, 8, 2048,
              "fluid cells across the box (Fig. 12: 100 in 0.4 m); 250 gives 1 mm cells, the converged grid of the "
              "convergence study");
    v.real("density_kg_per_m3", fluid.density_kg_per_m3, "kg/m^3", 1e-3, 1e6, "paper: '1' without units, read as g/cm^3");
    v.real("kinematic_viscosity_m2_per_s", fluid.kinematic_viscosity_m2_per_s, "m^2/s", 0, 10,
           "38 times water (Re ~16, within 2-D IB jellyfish studies' 10-300) so 1 mm cells resolve the Stokes "
           "layer; the paper's 1.304e-3, read as Pa s, gives 1.304e-6");
    v.choice("advection", fluid.advection,
             {fluid::AdvectionScheme::semi_lagrangian, fluid::AdvectionScheme::maccormack,
              fluid::AdvectionScheme::upwind2_rk2},
             "velocity advection: MacCormack (Selle et al. 2008, second order in space), the paper's semi-Lagrangian "
             "(Stam 1999), or upwind2_rk2 (Fromm upwind + Heun, CFL <= 0.5)");
    v.choice("viscosity_scheme", fluid.viscosity_scheme,
             {fluid::ViscosityScheme::backward_euler, fluid::ViscosityScheme::crank_nicolson},
             "viscous term in time: backward Euler (Stam 1999 §2.2, first order) or Crank-Nicolson (second order "
             "for that stage alone)");
    v.integer("fluid_threads", fluid.threads, 1, 16,
              "threads inside each fluid step; results are bitwise the same for any count (fluid/worker_pool.hpp); "
              "helps only on idle cores");
  }
  /// The coupling as the jellyfish kind offers it: kernel, semi_implicit, implicit_mobility,
  /// implicit_mass_factor, implicit_theta, implicit_reuse_tolerance (CouplingParams' own fields).
  template <class V>
  void describeCoupling(V& v) {
    v.choice("kernel", coupling.kernel, {ib::Kernel::bilinear, ib::Kernel::peskin4},
             "spreading/interpolation: Peskin's 4-point function, or the paper's bilinear hat (§3.2), stretched to "
             "kernel_radius_m; the hat's bell does not converge in its segments");
    v.boolean("semi_implicit", coupling.semi_implicit,
              "linearised implicit elastic forces (ib/coupling.hpp); false = explicit Peskin");
    v.choice("implicit_mobility", coupling.mobility, {ib::ImplicitMobility::stencil, ib::ImplicitMobility::local_mass},
             "fluid response assumed by the semi-implicit force: through the markers' stencils (ib/coupling.hpp), or "
             "each marker alone");
    v.real("implicit_mass_factor", coupling.implicit_mass_factor, "", 1e-6, 100,
           "local_mass only: added mass per marker in rho dx^2");
    v.real("implicit_theta", coupling.implicit_theta, "", 0.5, 1.0,
           "semi-implicit only: elastic force at X^n + theta dt U* (ib/coupling.hpp); 1 = backward Euler, which damps "
           "the recoil; 0.5 = the step's middle. 0.5 doubles the step at the same accuracy");
    v.real("implicit_reuse_tolerance", coupling.factor_reuse.tolerance, "", 0, 1e-4,
           "banded solve (>= 300 markers): relative residual accepted when refining on earlier LU factors, else "
           "refactored (ib/reused_banded_solve.hpp); 0 = every step");
  }
  /// viscosity_tolerance, dt_s, force_stage, blowup_speed_m_per_s, start_y_fraction.
  template <class V>
  void describeStep(V& v) {
    v.real("viscosity_tolerance", fluid.viscosity_tolerance, "", 1e-14, 1e-2,
           "relative residual of the implicit viscous solve (fluid/diffusion2.hpp); far below the step's and the "
           "grid's errors");
    v.real("dt_s", dt_s, "s", 1e-7, 0.1,
           "coupled step, first order in time (ib/coupling.hpp); with implicit_theta = 0.5 within about 2% of the "
           "step limit; the paper's 0.01 s is stable");
    v.choice("force_stage", fluid.force_stage,
             {fluid::ForceStage::before_advection, fluid::ForceStage::after_advection},
             "where the bell's force enters the fluid step: after the advection (a source of the momentum equation, "
             "Peskin 2002 §6), or before it (Stam 1999 §2.2, the paper's order)");
    v.real("blowup_speed_m_per_s", fluid.blowup_speed_m_per_s, "m/s", 1e-6, 1e6,
           "fluid speed taken as a blow-up (100x the swimming flow)");
    v.real("start_y_fraction", start_y_fraction, "", 0.05, 0.95,
           "aperture's starting height as a fraction of the box's (the bell swims up, its wake goes down): 0.18 m "
           "above the floor");
  }
};

/// The paper's setting where the defaults depart from it (Rudolf & Mould 2009 §3.2, Fig. 12): paperBell(),
/// paperActivation(), FluidParams' own fluid (water in a 0.4 m box of 100² cells, semi-Lagrangian, the force
/// before the advection), CouplingParams' own coupling (the grid's kernel, theta = 1), a 5 ms step, the
/// aperture a quarter of the box's height up.
SwimmerConfig paperSwimmer();

struct SwimmerObservation {
  double time_s = 0;
  fluid::Vec2 centroid_m;          // mean of the bell's markers (tentacles excluded)
  double diameter_ratio = 1;       // aperture width / drawn aperture width
};

class Swimmer {
 public:
  /// Throws std::invalid_argument naming the problem for unusable parameters.
  explicit Swimmer(const SwimmerConfig& config);

  /// One coupled step; accumulates the work. Throws as ImmersedBoundary2::step, and
  /// std::runtime_error when the bell's chain has crumpled (a step too large for the coupling).
  ib::CouplingStepReport step();

  SwimmerObservation observe() const;
  double time_s() const { return fluid_->time_s(); }
  const std::vector<fluid::Vec2>& markers_m() const { return coupling_->markers_m(); }
  const ib::ImmersedBoundary2& coupling() const { return *coupling_; }
  /// Work the body has done on the fluid since the start, Σ_steps Σ_k F_k · (X_k^{n+1} − X_k^n), J per
  /// metre of depth, with F the force actually spread (Peskin 2002: with adjoint spreading and
  /// interpolation this is the power the fluid receives).
  double fluidWork_j_per_m() const { return fluid_work_j_per_m_; }
  /// Elastic energy of the body now, J per metre of depth.
  double elasticEnergy_j_per_m() const;
  /// Work of the muscles' contractile elements since the start, J per metre of depth: the
  /// power −Σ_m T_m dr_m/dt (tension times the rate the rest length shortens) summed over steps,
  /// with the tension of the positions the step's force was evaluated at and the exact change
  /// of the rest lengths over the step.
  double muscleWork_j_per_m() const { return muscle_work_j_per_m_; }
  /// The same work by the energy balance −Σ T dr/dt = dE_elastic/dt + F · U: elastic energy gained
  /// plus work on the fluid. A cross-check of muscleWork_j_per_m(); the two differ by the
  /// semi-implicit step's numerical dissipation.
  double muscleWorkByBalance_j_per_m() const {
    return elasticEnergy_j_per_m() - initial_elastic_j_per_m_ + fluid_work_j_per_m_;
  }
  const fluid::FluidSolver2& fluid() const { return *fluid_; }
  fluid::FluidSolver2& fluid() { return *fluid_; }
  const JellyfishBody& body() const { return *body_; }
  const SwimmerConfig& config() const { return config_; }

 private:
  // Throws std::runtime_error when a bell segment is shorter than kCrumpledRatio or longer than
  // 1 / kCrumpledRatio of its rest length.
  void checkChain() const;
  static constexpr double kCrumpledRatio = 1.0 / 6.0;

  SwimmerConfig config_;
  std::unique_ptr<fluid::FluidSolver2> fluid_;
  std::unique_ptr<JellyfishBody> body_;
  std::unique_ptr<ib::ImmersedBoundary2> coupling_;
  double fluid_work_j_per_m_ = 0;
  double muscle_work_j_per_m_ = 0;
  std::vector<double> tension_;
  double initial_elastic_j_per_m_ = 0;
  std::vector<fluid::Vec2> previous_;
};

}  // namespace creaturelab::jellyfish
