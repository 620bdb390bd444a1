#pragma once
// Parameters of the 3-D incompressible fluid solver, for Eqs. 5–6 of Lentine, Gräfe & Fedkiw 2010
// (§4.1, "Navier–Stokes equations") with a viscous term:
//   ∂u/∂t + u·∇u = −∇p/ρ + ν ∇²u + f,   ∇·u = 0.
// Plain struct with in-class defaults; validate() says in words what is wrong. describe(v) names
// each field for the fluid3d kind (kinds/describe.hpp: name, unit, range, one-line doc).

#include <array>
#include <string>
#include <string_view>

namespace creaturelab::fluid3d {

/// Condition on one side of the box (ghost values as in the 2-D solver, fluid/boundary2.hpp).
enum class BoundaryType3 {
  periodic,   ///< the box repeats along this axis (both sides of the axis must be periodic)
  free_slip,  ///< solid: u·n = 0, ∂u_t/∂n = 0
  no_slip,    ///< solid: u = 0
  open,       ///< p = 0 on the side, ∂u/∂n = 0: fluid may leave or enter
  inflow      ///< fluid enters at a prescribed speed normal to the side, u_t = 0; the pressure sees a wall
};

/// The two sides of one axis.
struct AxisBoundary3 {
  BoundaryType3 low = BoundaryType3::free_slip;
  BoundaryType3 high = BoundaryType3::free_slip;
  double low_inflow_m_per_s = 0.0;   ///< speed into the box through the low side when it is inflow
  double high_inflow_m_per_s = 0.0;  ///< speed into the box through the high side when it is inflow
  bool periodic() const { return low == BoundaryType3::periodic; }
  /// Velocity (along +axis) on the side's own normal faces when they are known: zero on a solid wall,
  /// +speed on a low inflow side, −speed on a high one.
  double normalVelocity_m_per_s(bool high_side) const {
    if (high_side) return high == BoundaryType3::inflow ? -high_inflow_m_per_s : 0.0;
    return low == BoundaryType3::inflow ? low_inflow_m_per_s : 0.0;
  }
};

/// Sides of the box [0, Lx] × [0, Ly] × [0, Lz], by axis: x, y, z (z is up).
struct Boundaries3 {
  std::array<AxisBoundary3, 3> axis{};
  /// True when no side is open: the pressure is then defined up to a constant only.
  bool closed() const {
    for (const AxisBoundary3& a : axis)
      if (a.low == BoundaryType3::open || a.high == BoundaryType3::open) return false;
    return true;
  }
  bool anyInflow() const {
    for (const AxisBoundary3& a : axis)
      if (a.low == BoundaryType3::inflow || a.high == BoundaryType3::inflow) return true;
    return false;
  }
  static Boundaries3 allPeriodic() {
    Boundaries3 b;
    for (AxisBoundary3& a : b.axis) a = {BoundaryType3::periodic, BoundaryType3::periodic};
    return b;
  }
  static Boundaries3 allWalls(BoundaryType3 type) {
    Boundaries3 b;
    for (AxisBoundary3& a : b.axis) a = {type, type};
    return b;
  }
};

/// Velocity advection scheme (the 2-D solver's semi-Lagrangian ones, fluid/advection2.hpp).
enum class AdvectionScheme3 {
  semi_lagrangian,  ///< Stam 1999 §2.2: RK2 backtrace, trilinear interpolation (first order, diffusive)
  maccormack,       ///< Selle et al. 2008: forward + backward semi-Lagrangian, clamped (second order in space)
  upwind2_rk2       ///< Eulerian flux form, Fromm upwind + Heun (second order, CFL ≤ ⅓: upwind_advection3.hpp)
};

/// Pressure (projection) solver.
enum class PressureSolverType3 {
  spectral,  ///< exact: 1-D eigenbases along each axis (periodic, solid or open ends), any box
  mg_pcg     ///< conjugate gradients preconditioned by a multigrid V-cycle, to pressure_tolerance
};

/// Time integration of the viscous term ν∇²u.
enum class ViscosityScheme3 {
  backward_euler,  ///< (I − ν dt ∇²) u_new = u (Stam 1999 §2.2, first order in dt)
  crank_nicolson,  ///< (I − ½ν dt ∇²) u_new = (I + ½ν dt ∇²) u (second order in dt)
  explicit_euler   ///< u_new = (I + ν dt ∇²) u, stable for ν dt / dx² ≤ 1/6
};

/// How the projection meets the viscous stage (Guermond, Minev & Shen 2006, Comput. Methods Appl. Mech.
/// Engrg. 195, §3.1–3.2).
enum class ProjectionScheme3 {
  non_incremental,  ///< Chorin: the predictor has no pressure; the projection finds the whole pressure. Its
                    ///< steady state depends on dt beside walls (a numerical boundary layer of width √(ν dt))
  incremental       ///< Goda 1979 / van Kan 1986: the predictor subtracts (dt/ρ) ∇pⁿ, the projection finds the
                    ///< increment; steady states do not depend on dt. Not with Crank–Nicolson viscosity
                    ///< (validate() refuses it: unstable beside no-slip walls at ν dt / dx² ≥ 1)
};

enum class TimeStepPolicy3 {
  cfl_adaptive,  ///< dt = min(max_step_s, cfl_safety_factor · dx / max|u_component|)
  fixed          ///< dt = fixed_step_s
};

struct FluidParams3 {
  // --- domain: cubic cells of side domain_x_m / cells_x (= domain_y_m / cells_y = domain_z_m / cells_z)
  double domain_x_m = 0.4;
  double domain_y_m = 0.4;
  double domain_z_m = 0.4;
  int cells_x = 32;
  int cells_y = 32;
  int cells_z = 32;

  double density_kg_per_m3 = 1000.0;
  double kinematic_viscosity_m2_per_s = 1.0e-6;  ///< water at 20 °C

  Boundaries3 boundaries{};  ///< all free-slip
  AdvectionScheme3 advection = AdvectionScheme3::maccormack;
  ViscosityScheme3 viscosity_scheme = ViscosityScheme3::backward_euler;
  double viscosity_tolerance = 1e-10;  ///< CG stops at ‖b − A u‖∞ ≤ tol · ‖b‖∞
  int viscosity_max_iterations = 500;

  PressureSolverType3 pressure_solver = PressureSolverType3::mg_pcg;
  ProjectionScheme3 projection = ProjectionScheme3::non_incremental;
  /// MG-PCG stops at ‖b − A q‖∞ ≤ pressure_tolerance · ‖b‖∞ (= dx² max|∇·u| after the update).
  double pressure_tolerance = 1e-10;
  int pressure_max_iterations = 500;

  TimeStepPolicy3 time_step_policy = TimeStepPolicy3::cfl_adaptive;
  double cfl_safety_factor = 0.5;
  double max_step_s = 0.01;
  double fixed_step_s = 0.01;

  std::array<double, 3> body_acceleration_m_per_s2{0.0, 0.0, 0.0};  ///< gravity: {0, 0, −9.81}

  /// Threads that share a step, 1..16: bitwise the same results for any number.
  int threads = 1;
  /// A step whose velocity is not finite or exceeds this speed throws FluidBlowUpError3.
  double blowup_speed_m_per_s = 100.0;

  template <class V>
  void describe(V& v) {
    describeBox(v);
    v.real("density_kg_per_m3", density_kg_per_m3, "kg/m^3", 1e-6, 1e6, "fluid density (water: 1000)");
    v.real("kinematic_viscosity_m2_per_s", kinematic_viscosity_m2_per_s, "m^2/s", 0, 1e3,
           "nu (water at 20 C: 1e-6); 0 switches the viscous stage off");
    describeSides(v);
    describeSchemes(v);
    v.real("cfl_safety_factor", cfl_safety_factor, "", 1e-6, 10,
           "adaptive step: fraction of the CFL limit dx / max|u component| (capped by the scheme's bound)");
    v.real("max_step_s", max_step_s, "s", 1e-9, 10, "largest adaptive step");
    v.real("body_acceleration_x_m_per_s2", body_acceleration_m_per_s2[0], "m/s^2", -1e4, 1e4,
           "uniform body force per unit mass, x");
    v.real("body_acceleration_y_m_per_s2", body_acceleration_m_per_s2[1], "m/s^2", -1e4, 1e4,
           "uniform body force per unit mass, y");
    v.real("body_acceleration_z_m_per_s2", body_acceleration_m_per_s2[2], "m/s^2", -1e4, 1e4,
           "uniform body force per unit mass, z (up; gravity: -9.81)");
    v.integer("threads", threads, 1, 16, "threads sharing each step (results bitwise the same for any number)");
    v.real("blowup_speed_m_per_s", blowup_speed_m_per_s, "m/s", 1e-9, 1e9,
           "a step whose velocity exceeds this speed (or is not finite) ends the run as failed");
  }
  template <class V>
  void describeBox(V& v) {
    v.real("domain_x_m", domain_x_m, "m", 1e-6, 1e6, "box length along x");
    v.real("domain_y_m", domain_y_m, "m", 1e-6, 1e6, "box length along y");
    v.real("domain_z_m", domain_z_m, "m", 1e-6, 1e6, "box height (z is up); cells are cubes: the lengths over the cells agree");
    v.integer("cells_x", cells_x, 2, 1024, "cells along x");
    v.integer("cells_y", cells_y, 2, 1024, "cells along y");
    v.integer("cells_z", cells_z, 2, 1024, "cells along z");
  }
  /// side_<axis>_<low|high> and inflow_<axis>_<low|high>_m_per_s for the six sides.
  template <class V>
  void describeSides(V& v) {
    const char* axes[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
      for (const bool high : {false, true}) {
        const std::string side = std::string(axes[a]) + (high ? "_high" : "_low");
        AxisBoundary3& b = boundaries.axis[a];
        v.choice("side_" + side, high ? b.high : b.low,
                 {{"periodic", BoundaryType3::periodic},
                  {"free_slip", BoundaryType3::free_slip},
                  {"no_slip", BoundaryType3::no_slip},
                  {"open", BoundaryType3::open},
                  {"inflow", BoundaryType3::inflow}},
                 "the " + side + " side: periodic (both sides of the axis), free_slip, no_slip, open (p = 0) or inflow "
                 "(fluid enters at inflow_" + side + "_m_per_s, u_t = 0)");
        v.real("inflow_" + side + "_m_per_s", high ? b.high_inflow_m_per_s : b.low_inflow_m_per_s, "m/s", -1e3, 1e3,
               "speed into the box through the " + side + " side when it is inflow (Lentine et al. 2010 §7.1: the "
               "floor's source)");
      }
  }
  /// advection, viscosity_scheme, pressure_solver and the iterative solves' tolerances.
  template <class V>
  void describeSchemes(V& v) {
    v.choice("advection", advection,
             {{"semi_lagrangian", AdvectionScheme3::semi_lagrangian},
              {"maccormack", AdvectionScheme3::maccormack},
              {"upwind2_rk2", AdvectionScheme3::upwind2_rk2}},
             "semi_lagrangian (Stam 1999, first order), maccormack (Selle et al. 2008, limited) or upwind2_rk2 "
             "(Fromm upwind + Heun, second order, CFL <= 1/3)");
    v.choice("viscosity_scheme", viscosity_scheme,
             {{"backward_euler", ViscosityScheme3::backward_euler},
              {"crank_nicolson", ViscosityScheme3::crank_nicolson},
              {"explicit_euler", ViscosityScheme3::explicit_euler}},
             "viscous term in time: backward Euler (Stam 1999 §2.2, first order), Crank-Nicolson (second order) "
             "or explicit Euler (stable for nu dt / dx^2 <= 1/6)");
    v.choice("projection", projection,
             {{"non_incremental", ProjectionScheme3::non_incremental}, {"incremental", ProjectionScheme3::incremental}},
             "non_incremental (Chorin: steady states beside walls depend on dt) or incremental (the previous "
             "pressure in the predictor, Guermond et al. 2006 §3.2: they do not; not with crank_nicolson)");
    v.choice("pressure_solver", pressure_solver,
             {{"mg_pcg", PressureSolverType3::mg_pcg}, {"spectral", PressureSolverType3::spectral}},
             "projection: multigrid-preconditioned CG to pressure_tolerance, or the exact eigenbasis solve "
             "(FFT along periodic and walled axes of a power-of-two length)");
    v.real("pressure_tolerance", pressure_tolerance, "", 1e-16, 1e-2,
           "MG-PCG stops at |b - A q|inf <= tolerance |b|inf");
    v.integer("pressure_max_iterations", pressure_max_iterations, 1, 100000, "MG-PCG iteration limit");
    v.real("viscosity_tolerance", viscosity_tolerance, "", 1e-16, 1e-2,
           "implicit viscosity: CG stops at |b - A u|inf <= tolerance |b|inf");
    v.integer("viscosity_max_iterations", viscosity_max_iterations, 1, 100000, "viscosity CG iteration limit");
  }

  double cellSize_m() const { return domain_x_m / cells_x; }
  /// Empty when usable; otherwise one sentence per problem, joined by "; ".
  std::string validate() const;
};

std::string_view toString(BoundaryType3 type);
std::string_view toString(AdvectionScheme3 scheme);
std::string_view toString(PressureSolverType3 type);
std::string_view toString(ViscosityScheme3 scheme);
std::string_view toString(ProjectionScheme3 scheme);

}  // namespace creaturelab::fluid3d
