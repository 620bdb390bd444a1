#pragma once
// Parameters of the 2-D incompressible fluid solver (Rudolf & Mould 2009,
// §3.2, Eq. 1: ∂u/∂t = ν ∇²u − u·∇u − ∇p/ρ + F,   ∇·u = 0).
// Plain struct with in-class defaults; validate() says in words what is wrong. The describe*(v)
// templates name each field for the fluid kind (kinds/describe.hpp: name, unit, range, one-line doc),
// and the in-class defaults are that kind's.

#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace creaturelab::fluid {

/// Boundary condition on one wall of the rectangular domain (Griebel et al. 1998, ch. 2
/// "initial and boundary conditions"; implemented with ghost values, ch. 3).
enum class WallType {
  free_slip,  ///< no flow through, no shear: u·n = 0, ∂u_t/∂n = 0 (the jellyfish paper's, §3.2)
  no_slip,    ///< no flow through, fluid sticks: u = 0
  moving,     ///< no flow through, fluid moves with the wall: u·n = 0, u_t = tangential velocity
  open,       ///< p = 0 on the wall, ∂u/∂n = 0; fluid may leave or enter (outflow condition)
  inflow      ///< a prescribed flux: fluid enters at inflow_m_per_s normal to the wall, u_t = tangential
              ///< velocity; the projection keeps it (Neumann for the pressure, like a solid wall)
};

/// One wall. The tangential direction is +x for the bottom and top walls and +y for the left
/// and right walls.
struct Wall {
  WallType type = WallType::free_slip;
  double tangential_velocity_m_per_s = 0.0;  ///< used only by WallType::moving and WallType::inflow
  double inflow_m_per_s = 0.0;               ///< speed into the domain; used only by WallType::inflow
};

/// The four walls of the domain [0, width] × [0, height].
struct Walls {
  Wall left{};
  Wall right{};
  Wall bottom{};
  Wall top{};
  /// True when no wall is open: the pressure is then defined up to a constant only (an inflow wall
  /// then has nowhere to leave: validate() refuses it).
  bool closed() const {
    return left.type != WallType::open && right.type != WallType::open && bottom.type != WallType::open &&
           top.type != WallType::open;
  }
  bool anyInflow() const {
    return left.type == WallType::inflow || right.type == WallType::inflow || bottom.type == WallType::inflow ||
           top.type == WallType::inflow;
  }
  /// wall_<side> and wall_<side>_velocity_m_per_s for left, right, bottom, top (inflow is not offered).
  template <class V>
  void describe(V& v) {
    const std::pair<const char*, Wall*> sides[] = {{"left", &left}, {"right", &right}, {"bottom", &bottom}, {"top", &top}};
    for (const auto& [side, wall] : sides) {
      v.choice(std::string("wall_") + side, wall->type,
               {WallType::free_slip, WallType::no_slip, WallType::moving, WallType::open},
               std::string(side) + " wall: free_slip (the paper's), no_slip, moving, open (p = 0)");
      v.real(std::string("wall_") + side + "_velocity_m_per_s", wall->tangential_velocity_m_per_s, "m/s", -1e3, 1e3,
             std::string("tangential velocity of the ") + side + " wall when moving");
    }
  }
};

/// Velocity advection scheme.
enum class AdvectionScheme {
  semi_lagrangian,  ///< Stam 1999 §2.2: RK2 backtrace, bilinear interpolation (first order, diffusive)
  maccormack,       ///< Selle et al. 2008: forward + backward semi-Lagrangian, clamped (second order)
  upwind2_rk2       ///< Eulerian flux form, Fromm upwind + Heun (second order, CFL ≤ ½: upwind_advection2.hpp)
};

/// Largest CFL number (max velocity component · dt / dx) at which the scheme is stable:
/// infinite for the semi-Lagrangian ones; ½ for upwind2_rk2 (linear von Neumann bound in 2-D,
/// upwind_advection2.hpp). FluidSolver2 refuses a step above it.
double maxStableCflNumber(AdvectionScheme scheme);

/// Pressure (projection) solver. Both give the same answer to round-off / tolerance.
enum class PressureSolverType {
  fast_direct,  ///< transform along one axis + tridiagonal solves along the other (exact, O(N log N))
  pcg           ///< MIC(0)-preconditioned conjugate gradients, to pressure_tolerance
};

/// Implicit viscosity solver. Both solve the same backward-Euler system; they agree to
/// viscosity_tolerance (not bitwise).
enum class ViscositySolverType {
  iterative,   ///< Richardson sweeps, then Chebyshev or CG, to viscosity_tolerance (diffusion2.hpp); the default
  fast_direct  ///< transform + tridiagonal solves, exact to round-off (fast_diffusion2.hpp)
};

/// Time integration of the viscous term.
enum class ViscosityScheme {
  backward_euler,  ///< (I − ν dt ∇²) u_new = u: Stam 1999 §2.2, first order in dt; the default
  crank_nicolson   ///< (I − ½ν dt ∇²) u_new = (I + ½ν dt ∇²) u: second order in dt for this stage
};

/// Where the external force density (the immersed boundary's) enters the step's splitting.
/// Both are first order in dt; they differ in whether the force's velocity increment is advected.
enum class ForceStage {
  before_advection,  ///< u += dt f/ρ, then advect (Stam 1999 §2.2, "add force"; Rudolf & Mould §3.2); the default
  after_advection    ///< advect u^n, then u += dt f/ρ: the force is a source of the momentum equation at the
                     ///< step's start (Peskin 2002 §6), its increment is not carried by −u·∇u
};

/// How the time step is chosen.
enum class TimeStepPolicy {
  cfl_adaptive,  ///< dt = min(max_step_s, cfl_safety_factor · dx / max|u_component|)
  fixed          ///< dt = fixed_step_s
};

struct FluidParams {
  // --- domain: [0, width] × [0, height], square cells of side width / cells_x = height / cells_y
  double domain_width_m = 0.4;  ///< ten jellyfish diameters of 40 mm (paper §3.2, Fig. 12)
  double domain_height_m = 0.4;
  int cells_x = 100;  ///< paper Fig. 12: fluid grid n = 100
  int cells_y = 100;
  /// A square box, side domain_m and `cells` per side: read into the width and cells_x, then makeSquare().
  template <class V>
  void describeSquareBox(V& v) {
    v.real("domain_m", domain_width_m, "m", 1e-6, 1e6,
           "side of the square box (Rudolf & Mould Fig. 12: 0.4 m, ten 40 mm bell diameters)");
    v.integer("cells", cells_x, 4, 4096, "cells per side (Rudolf & Mould Fig. 12: 100)");
  }
  void makeSquare() {
    domain_height_m = domain_width_m;
    cells_y = cells_x;
  }

  // --- fluid. Paper Fig. 12 lists ν = 1.304e-3 and ρ = 1 without units; 1.304e-3 Pa·s is the
  // dynamic viscosity of water at 10 °C, i.e. ν = 1.304e-6 m²/s at ρ = 1000 kg/m³ (ρ = 1 g/cm³).
  double density_kg_per_m3 = 1000.0;
  double kinematic_viscosity_m2_per_s = 1.304e-6;
  template <class V>
  void describeFluid(V& v) {
    v.real("density_kg_per_m3", density_kg_per_m3, "kg/m^3", 1e-6, 1e6,
           "fluid density (paper: '1' without units, read as g/cm^3)");
    v.real("kinematic_viscosity_m2_per_s", kinematic_viscosity_m2_per_s, "m^2/s", 0, 1e3,
           "nu (paper: 1.304e-3, read as Pa s, water at 10 C, over 1000 kg/m^3)");
  }

  Walls walls{};  ///< all free-slip, as in the paper (§3.2)

  AdvectionScheme advection = AdvectionScheme::semi_lagrangian;
  ForceStage force_stage = ForceStage::before_advection;

  // --- pressure projection
  PressureSolverType pressure_solver = PressureSolverType::fast_direct;
  /// PCG stops when both the relative residual of the Poisson equation ‖b − A p‖∞ / ‖b‖∞ and
  /// max|∇·u| dx / max|u| are ≤ pressure_tolerance, or the divergence is at round-off
  /// (1e-14 max|u| / dx); see pcg_pressure_solver2.hpp. The fast direct solver is exact.
  double pressure_tolerance = 1e-10;
  int pressure_max_iterations = 5000;

  // --- implicit viscosity (backward Euler, Stam 1999 §2.2)
  /// iterative is the default (the converged results were computed with it); fast_direct is
  /// faster only for large ν dt / dx² (fast_diffusion2.hpp).
  ViscositySolverType viscosity_solver = ViscositySolverType::iterative;
  ViscosityScheme viscosity_scheme = ViscosityScheme::backward_euler;
  double viscosity_tolerance = 1e-10;  ///< ‖b − A u‖∞ ≤ tol · ‖b‖∞
  int viscosity_max_iterations = 1000;
  template <class V>
  void describeViscosityScheme(V& v) {
    v.choice("viscosity_scheme", viscosity_scheme, {ViscosityScheme::backward_euler, ViscosityScheme::crank_nicolson},
             "viscous term in time: backward Euler (Stam 1999 §2.2, first order) or Crank-Nicolson (second order "
             "for that stage alone)");
  }

  template <class V>
  void describeAdvection(V& v) {
    v.choice("advection", advection,
             {AdvectionScheme::semi_lagrangian, AdvectionScheme::maccormack, AdvectionScheme::upwind2_rk2},
             "semi_lagrangian (Stam 1999, linear interpolation), maccormack (limited, second order) or upwind2_rk2 "
             "(Fromm upwind + Heun, second order, CFL <= 0.5)");
  }
  /// advection, pressure_solver, viscosity_solver.
  template <class V>
  void describeSchemes(V& v) {
    describeAdvection(v);
    v.choice("pressure_solver", pressure_solver, {PressureSolverType::fast_direct, PressureSolverType::pcg},
             "exact projection: transform + tridiagonal (uniform box) or MIC(0)-PCG to 1e-10");
    v.choice("viscosity_solver", viscosity_solver, {ViscositySolverType::iterative, ViscositySolverType::fast_direct},
             "implicit viscosity: iterative sweeps (fast for water-like nu dt / dx^2) or the fast direct solve "
             "(exact; faster for very viscous fluids)");
  }

  // --- time step (Griebel et al. 1998, ch. 3: the CFL condition dt < dx / |u|max)
  TimeStepPolicy time_step_policy = TimeStepPolicy::cfl_adaptive;
  /// Fraction of the CFL limit. Semi-Lagrangian advection is stable beyond 1; accuracy is not.
  /// (The paper used 0.001 with the elastic jellyfish, §3.2; the fluid alone does not need it.)
  double cfl_safety_factor = 0.5;
  double max_step_s = 0.01;    ///< upper bound of the adaptive step (paper §4: 0.01 s is the edge)
  double fixed_step_s = 0.01;  ///< step of the fixed policy
  /// cfl_safety_factor, max_step_s (the adaptive policy's).
  template <class V>
  void describeAdaptiveStep(V& v) {
    v.real("cfl_safety_factor", cfl_safety_factor, "", 1e-6, 10,
           "fraction of the CFL limit dx / max|u| (paper used 0.001 with the bell)");
    v.real("max_step_s", max_step_s, "s", 1e-9, 10, "largest adaptive step (paper §4: instability near 0.01 s)");
  }

  // --- uniform body force per unit mass (gravity: body_acceleration_y_m_per_s2 = -9.81).
  // In a closed box of uniform density it is balanced exactly by a hydrostatic pressure.
  double body_acceleration_x_m_per_s2 = 0.0;
  double body_acceleration_y_m_per_s2 = 0.0;
  template <class V>
  void describeBodyForce(V& v) {
    v.real("body_acceleration_x_m_per_s2", body_acceleration_x_m_per_s2, "m/s^2", -1e4, 1e4,
           "uniform body force per unit mass, x");
    v.real("body_acceleration_y_m_per_s2", body_acceleration_y_m_per_s2, "m/s^2", -1e4, 1e4,
           "uniform body force per unit mass, y (gravity: -9.81)");
  }

  /// Threads that share the work of one step, 1..16 (1: none). Results are bitwise the same for
  /// any number (the work is cut by index only; see worker_pool.hpp): this changes only the time.
  int threads = 1;
  template <class V>
  void describeThreads(V& v) {
    v.integer("fluid_threads", threads, 1, 16,
              "threads inside each fluid step; results are bitwise the same for any count (fluid/worker_pool.hpp); "
              "helps only on idle cores");
  }

  /// A step whose velocity is not finite or exceeds this speed throws FluidBlowUpError.
  double blowup_speed_m_per_s = 100.0;
  template <class V>
  void describeBlowupSpeed(V& v) {
    v.real("blowup_speed_m_per_s", blowup_speed_m_per_s, "m/s", 1e-6, 1e6,
           "a fluid faster than this (or not finite) stops the run as a blow-up");
  }

  double cellSize_m() const { return domain_width_m / cells_x; }
  /// μ = ρ ν, Pa s.
  double dynamicViscosity_pa_s() const { return density_kg_per_m3 * kinematic_viscosity_m2_per_s; }

  /// Empty when the parameters are usable; otherwise one sentence per problem, joined by "; ".
  std::string validate() const;
};

std::string_view to_string(WallType type);
std::string_view to_string(AdvectionScheme scheme);
std::string_view to_string(PressureSolverType type);
std::string_view to_string(TimeStepPolicy policy);
std::string_view to_string(ViscositySolverType type);
std::string_view to_string(ViscosityScheme scheme);
std::string_view to_string(ForceStage stage);
/// Inverses of to_string (the names are the enumerator names); std::nullopt for unknown names.
std::optional<WallType> parseWallType(std::string_view name);
std::optional<AdvectionScheme> parseAdvectionScheme(std::string_view name);
std::optional<PressureSolverType> parsePressureSolverType(std::string_view name);
std::optional<TimeStepPolicy> parseTimeStepPolicy(std::string_view name);
std::optional<ViscositySolverType> parseViscositySolverType(std::string_view name);
std::optional<ViscosityScheme> parseViscosityScheme(std::string_view name);
std::optional<ForceStage> parseForceStage(std::string_view name);

}  // namespace creaturelab::fluid
