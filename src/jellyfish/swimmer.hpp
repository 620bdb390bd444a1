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

// The jellyfish kind's fluid, the setting the jellyfish convergence experiments refine (grid, step,
// scheme and box): a 0.25 m by 0.36 m free-slip box of 2/3 mm cells, a fluid 38
// times as viscous as water, MacCormack advection, the bell's force after the advection, a fixed step.
fluid::FluidParams jellyfishFluid();
// Its coupling: Peskin's kernel stretched to the bell's 4 mm thickness on that grid (3 cells per
// kernel unit), the semi-implicit force at the step's middle (theta = 1/2).
ib::CouplingParams jellyfishCoupling();

struct SwimmerConfig {
  BellParams bell;
  ActivationParams activation;
  fluid::FluidParams fluid = jellyfishFluid();  // domain, grid, water, walls, advection
  ib::CouplingParams coupling = jellyfishCoupling();
  // The tentacle markers' own kernel stretch (ib::CouplingParams::marker_kernel_scales): filaments spread
  // narrower than the bell. 0: the bell's (coupling.kernel_scale). 1: the kind's 4/3 mm filaments on 2/3 mm cells.
  int tentacle_kernel_scale = 1;
  double dt_s = 1.0 / 300.0;  // coupled step (see ib/coupling.hpp on stability); = fluid.fixed_step_s
  // Where the middle of the aperture starts, as fractions of the domain (apex toward +y).
  double start_x_fraction = 0.5;
  double start_y_fraction = 0.5;

  /// viscosity_tolerance, dt_s, force_stage, start_y_fraction (the rest of the fluid and the coupling
  /// describe themselves: FluidParams, CouplingParams).
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
    v.real("start_y_fraction", start_y_fraction, "", 0.05, 0.95,
           "aperture's starting height as a fraction of the box's (the bell swims up, its wake goes down): 0.18 m "
           "above the floor");
  }

  /// "" if usable (the bell's, the activation's and the fluid's validate(), a positive step, a
  /// tentacle kernel stretch >= 0), else one sentence per problem.
  std::string validate() const;
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
