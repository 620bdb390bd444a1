// Each stage of the fluid step alone against an analytic answer (Jet's habit).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

#include "fluid/advection2.hpp"
#include "fluid/boundary2.hpp"
#include "fluid/diagnostics2.hpp"
#include "fluid/diffusion2.hpp"
#include "fluid/fast_diffusion2.hpp"
#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"
#include "fluid/staggered_sampler2.hpp"
#include "fluid/tracers2.hpp"

namespace creaturelab::fluid {
namespace {

FluidParams box(int n, double size_m) {
  FluidParams params;
  params.cells_x = params.cells_y = n;
  params.domain_width_m = params.domain_height_m = size_m;
  return params;
}

void only(FluidSolver2& solver, bool forces, bool advection, bool viscosity, bool pressure) {
  solver.stages() = FluidStages{forces, advection, viscosity, pressure, false};
}

// Jet (GridFluidSolver2 tests): with advection, viscosity and pressure off, one 0.01 s step
// under g = −10 m/s² gives v = −0.1 m/s.
TEST(ExternalForces, GravityOnlyStepGivesTheAnalyticVelocity) {
  FluidParams params = box(8, 1.0);
  params.body_acceleration_y_m_per_s2 = -10.0;
  FluidSolver2 solver(params);
  only(solver, true, false, false, false);
  solver.step(0.01);
  const MacGrid2& g = solver.grid();
  for (int j = 1; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) EXPECT_DOUBLE_EQ(g.v_m_per_s(i, j), -0.1);
  }
  for (int i = 0; i < g.nx; ++i) {
    EXPECT_EQ(g.v_m_per_s(i, 0), 0.0);  // solid walls: no flow through
    EXPECT_EQ(g.v_m_per_s(i, g.ny), 0.0);
  }
  EXPECT_EQ(maxAbs(g.u_m_per_s), 0.0);
  EXPECT_DOUBLE_EQ(solver.time_s(), 0.01);
}

// With the projection on, gravity in a closed box is balanced by a hydrostatic pressure.
TEST(ExternalForces, GravityInAClosedBoxIsHydrostatic) {
  FluidParams params = box(16, 1.0);
  params.body_acceleration_y_m_per_s2 = -9.81;
  FluidSolver2 solver(params);
  only(solver, true, false, false, true);
  solver.step(0.01);
  const MacGrid2& g = solver.grid();
  EXPECT_LT(maxVelocityComponent_m_per_s(g), 1e-14);
  for (int j = 0; j + 1 < g.ny; ++j) {
    const double dp_dy = (g.pressure_pa(5, j + 1) - g.pressure_pa(5, j)) / g.dx_m;
    EXPECT_NEAR(dp_dy, -params.density_kg_per_m3 * 9.81, 1e-9);  // ∂p/∂y = ρ g
  }
}

TEST(ExternalForces, ForceDensityIsDividedByDensity) {
  FluidParams params = box(8, 1.0);
  params.density_kg_per_m3 = 1000.0;
  FluidSolver2 solver(params);
  solver.forceDensity_n_per_m3().x.fill(2.0);  // N/m³
  solver.forceDensity_n_per_m3().y.fill(-4.0);
  only(solver, true, false, false, false);
  solver.step(0.5);
  EXPECT_DOUBLE_EQ(solver.grid().u_m_per_s(3, 3), 0.5 * 2.0 / 1000.0);
  EXPECT_DOUBLE_EQ(solver.grid().v_m_per_s(3, 3), -0.5 * 4.0 / 1000.0);
  EXPECT_EQ(solver.grid().u_m_per_s(0, 3), 0.0);  // solid wall face ignored
}

// Uniform flow is preserved exactly by advection (both schemes).
TEST(Advection, PreservesUniformFlowExactly) {
  for (AdvectionScheme scheme : {AdvectionScheme::semi_lagrangian, AdvectionScheme::maccormack}) {
    for (bool fully_open : {false, true}) {
      Walls walls;
      walls.left.type = walls.right.type = WallType::open;  // a channel
      if (fully_open) walls.bottom.type = walls.top.type = WallType::open;
      MacGrid2 grid(16, 12, 0.05);
      grid.u_m_per_s.fill(0.3);
      grid.v_m_per_s.fill(fully_open ? -0.2 : 0.0);
      enforceWallNormalVelocity(grid, walls);
      auto advection = makeAdvectionSolver(scheme);
      Array2 u, v;
      advection->advectVelocity(grid, walls, 0.37, u, v);  // CFL > 2
      EXPECT_EQ(u, grid.u_m_per_s) << to_string(scheme);
      EXPECT_EQ(v, grid.v_m_per_s) << to_string(scheme);
    }
  }
}

TEST(Step, PreservesUniformChannelFlowExactlyWithEveryStage) {
  for (AdvectionScheme scheme : {AdvectionScheme::semi_lagrangian, AdvectionScheme::maccormack}) {
    for (PressureSolverType pressure : {PressureSolverType::fast_direct, PressureSolverType::pcg}) {
      FluidParams params = box(16, 1.0);
      params.walls.left.type = params.walls.right.type = WallType::open;
      params.kinematic_viscosity_m2_per_s = 1e-3;
      params.advection = scheme;
      params.pressure_solver = pressure;
      FluidSolver2 solver(params);
      solver.grid().u_m_per_s.fill(0.25);
      const Array2 initial = solver.grid().u_m_per_s;
      for (int s = 0; s < 3; ++s) solver.step();
      EXPECT_EQ(solver.grid().u_m_per_s, initial) << to_string(scheme) << ", " << to_string(pressure);
      EXPECT_EQ(maxAbs(solver.grid().v_m_per_s), 0.0);
    }
  }
}

// The semi-Lagrangian trace samples faces four (AVX2), two (SSE2) or one at a time; each face must
// get the scalar arithmetic of the documented trace, bit for bit, so that the grouping (and so the
// instruction set the fluid library was built with, CMakeLists.txt) never changes a result. A
// rough flow on 37 × 23 cells (rows of 36, 37 and 38 faces: every tail length), with large
// steps whose feet leave the box (the clamp), and small ones (a fiftieth of a cell, the jellyfish's
// CFL) where four neighbouring faces mostly share a stencil row (the sampler's contiguous loads)
// and, where the velocity changes sign, do not (its gather).
TEST(Advection, SemiLagrangianFacesGetTheScalarTraceBitForBit) {
  const int nx = 37, ny = 23;
  const double dx = 0.01;
  MacGrid2 grid(nx, ny, dx);
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx; ++i) grid.u_m_per_s(i, j) = 0.3 * std::sin(0.7 * i + 1.3 * j) + 0.05 * ((i * 7 + j) % 3);
  for (int j = 1; j < ny; ++j)
    for (int i = 0; i < nx; ++i) grid.v_m_per_s(i, j) = 0.3 * std::cos(1.1 * i - 0.4 * j) - 0.05 * ((i + j * 5) % 4);
  const Walls walls;
  StaggeredComponent2 u, v;
  u.assign(FaceAxis::x, grid.u_m_per_s, walls);
  v.assign(FaceAxis::y, grid.v_m_per_s, walls);
  const Array2& up = u.padded();  // up(i, j + 1) = u(i, j)
  const Array2& vp = v.padded();  // vp(i + 1, j) = v(i, j)
  for (double dt : {0.0005, 0.004, 0.05}) {
    const double c = dt / dx;
    SemiLagrangianAdvection2 advection;
    Array2 u_out, v_out;
    advection.advectVelocity(grid, walls, dt, u_out, v_out);
    auto foot = [&](double X, double Y, double vel_x, double vel_y) {
      const double xm = X - 0.5 * c * vel_x, ym = Y - 0.5 * c * vel_y;
      return std::pair{X - c * u.sample(xm, ym), Y - c * v.sample(xm, ym)};
    };
    for (int j = 0; j < ny; ++j)
      for (int i = 1; i < nx; ++i) {
        const double other = 0.25 * ((vp(i, j) + vp(i + 1, j)) + (vp(i, j + 1) + vp(i + 1, j + 1)));
        const auto [X, Y] = foot(i, j + 0.5, grid.u_m_per_s(i, j), other);
        ASSERT_EQ(u_out(i, j), u.sample(X, Y)) << "u face " << i << ", " << j << ", dt " << dt;
      }
    for (int j = 1; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double other = 0.25 * ((up(i, j) + up(i + 1, j)) + (up(i, j + 1) + up(i + 1, j + 1)));
        const auto [X, Y] = foot(i + 0.5, j, other, grid.v_m_per_s(i, j));
        ASSERT_EQ(v_out(i, j), v.sample(X, Y)) << "v face " << i << ", " << j << ", dt " << dt;
      }
  }
}

TEST(Advection, FluidAtRestStaysAtRest) {
  MacGrid2 grid(10, 10, 0.1);
  Walls walls;
  walls.top.type = WallType::moving;
  walls.top.tangential_velocity_m_per_s = 0.0;
  MacCormackAdvection2 advection;
  Array2 u, v;
  advection.advectVelocity(grid, walls, 0.1, u, v);
  EXPECT_EQ(maxAbs(u), 0.0);
  EXPECT_EQ(maxAbs(v), 0.0);
}

// Both viscosity solvers: the iterative (to a tolerance) and the fast direct (exact to round-off).
std::vector<std::unique_ptr<DiffusionSolver2>> viscosity_solvers(double tolerance, int max_iterations) {
  std::vector<std::unique_ptr<DiffusionSolver2>> solvers;
  solvers.push_back(std::make_unique<ImplicitDiffusion2>(tolerance, max_iterations));
  solvers.push_back(std::make_unique<FastDiffusion2>(tolerance));
  return solvers;
}

// The free-slip box's lowest v eigenmode on n × n cells: v on faces (i + ½, j) is
// cos(π (i + ½) / n) in x (Neumann: free-slip left/right ghosts) times sin(π j / n) in y (zero on
// the solid bottom/top faces); u is zero.
void set_box_eigenmode(MacGrid2& grid, int n) {
  const double pi = std::numbers::pi;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i < n; ++i) grid.v_m_per_s(i, j) = std::cos(pi * (i + 0.5) / n) * std::sin(pi * j / n);
}
// Its eigenvalue of −∇² (the 5-point operator), 1/m².
double box_eigenvalue_per_m2(int n, double dx) {
  const double s = std::sin(std::numbers::pi / (2.0 * n));
  return (4.0 * s * s + 4.0 * s * s) / (dx * dx);
}

// Couette walls: open at both ends, a no-slip floor and a top moving at top_speed.
Walls couette_walls(double top_speed) {
  Walls walls;
  walls.left.type = walls.right.type = WallType::open;
  walls.bottom.type = WallType::no_slip;
  walls.top.type = WallType::moving;
  walls.top.tangential_velocity_m_per_s = top_speed;
  return walls;
}

// A discrete eigenmode of the free-slip box's viscous operator decays by exactly
// 1 / (1 + ν dt λ) in one backward-Euler step, with either solver.
TEST(Viscosity, EigenmodeDecaysByTheBackwardEulerFactor) {
  const int n = 16;
  const double dx = 0.1, nu = 0.02, dt = 0.3;
  for (auto& diffusion : viscosity_solvers(1e-13, 100)) {
    MacGrid2 grid(n, n, dx);
    set_box_eigenmode(grid, n);
    const MacGrid2 initial = grid;
    const LinearSolveReport report = diffusion->diffuseVelocity(grid, Walls{}, nu, dt);
    EXPECT_TRUE(report.converged);
    const double factor = 1.0 / (1.0 + nu * dt * box_eigenvalue_per_m2(n, dx));
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i < n; ++i) EXPECT_NEAR(grid.v_m_per_s(i, j), factor * initial.v_m_per_s(i, j), 1e-12);
    EXPECT_EQ(maxAbs(grid.u_m_per_s), 0.0);
  }
}

// Crank–Nicolson (FluidParams::viscosity_scheme): the same eigenmode decays by
// (1 − ½α λ)/(1 + ½α λ), which differs from backward Euler's 1/(1 + α λ) by far more than the
// tolerance, and with walls that move, the steady Couette profile is a fixed point of the step
// (the explicit half carries the same wall terms as the implicit one).
TEST(Viscosity, CrankNicolsonEigenmodeAndCouetteFixedPoint) {
  const int n = 16;
  const double dx = 0.1, nu = 0.02, dt = 0.3;
  for (auto& diffusion : viscosity_solvers(1e-13, 100)) {
    MacGrid2 grid(n, n, dx);
    set_box_eigenmode(grid, n);
    const MacGrid2 initial = grid;
    EXPECT_TRUE(diffusion->diffuseVelocity(grid, Walls{}, nu, dt, ViscosityScheme::crank_nicolson).converged);
    const double half = 0.5 * nu * dt * box_eigenvalue_per_m2(n, dx);
    const double factor = (1.0 - half) / (1.0 + half);
    ASSERT_GT(std::abs(factor - 1.0 / (1.0 + 2.0 * half)), 1e-4);  // ≫ the 1e-12 checked below
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i < n; ++i) EXPECT_NEAR(grid.v_m_per_s(i, j), factor * initial.v_m_per_s(i, j), 1e-12);
    EXPECT_EQ(maxAbs(grid.u_m_per_s), 0.0);
  }
  const int nx = 8, ny = 10;
  const double top_speed = 0.7;
  const Walls walls = couette_walls(top_speed);
  for (auto& diffusion : viscosity_solvers(1e-14, 2000)) {
    MacGrid2 grid(nx, ny, dx);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i <= nx; ++i) grid.u_m_per_s(i, j) = top_speed * (j + 0.5) / ny;
    diffusion->diffuseVelocity(grid, walls, 1.0, 0.05, ViscosityScheme::crank_nicolson);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i <= nx; ++i) EXPECT_NEAR(grid.u_m_per_s(i, j), top_speed * (j + 0.5) / ny, 1e-12);
  }
}

// A no-slip floor and a lid moving at 0.05 m/s (free-slip sides): walls with ghost terms.
Walls floor_and_moving_lid() {
  Walls walls;
  walls.bottom.type = WallType::no_slip;
  walls.top.type = WallType::moving;
  walls.top.tangential_velocity_m_per_s = 0.05;
  return walls;
}
// A rough field for the viscosity solvers: the vortex pair with grid-scale noise of 1e-3 m/s on
// the unknown faces, the solid walls' normal faces zero (the stage's precondition).
MacGrid2 rough_vortex(int nx, int ny, double dx, const Walls& walls) {
  MacGrid2 grid(nx, ny, dx);
  setVortexPair(grid, VortexPair{});
  enforceWallNormalVelocity(grid, walls);
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx; ++i) grid.u_m_per_s(i, j) += 1e-3 * (((i * 7 + j * 13) % 5) - 2);
  for (int j = 1; j < ny; ++j)
    for (int i = 0; i < nx; ++i) grid.v_m_per_s(i, j) += 1e-3 * (((i * 11 + j * 3) % 7) - 3);
  return grid;
}

// Where Richardson sweeps replace CG (10 α ≤ ImplicitDiffusion2::kSweepContraction), the
// result meets the same tolerance: against a solve to 1e-14 (the sweeps cannot reach it in
// kMaxSweeps, so CG finishes it), the default 1e-10 solve differs by at most 1e-10 ‖b‖∞
// (A = I + α L with L ≥ 0, so ‖x − x*‖ ≤ ‖b − A x‖). A rough field (grid-scale noise on a
// vortex) at two α near the limit, with no-slip and moving walls.
TEST(Viscosity, RichardsonSweepsMeetTheToleranceOfCg) {
  const int nx = 40, ny = 30;
  const double dx = 0.01;
  const Walls walls = floor_and_moving_lid();
  for (double ten_alpha : {0.06, 0.1}) {
    const double alpha = 0.1 * ten_alpha;
    ASSERT_LE(ten_alpha, ImplicitDiffusion2::kSweepContraction);
    MacGrid2 grid = rough_vortex(nx, ny, dx, walls);
    const double b_norm = std::max(maxAbs(grid.u_m_per_s), maxAbs(grid.v_m_per_s)) + 2.0 * alpha * 0.05;
    MacGrid2 tight = grid;
    const double nu = 1e-3, dt = alpha * dx * dx / nu;
    ImplicitDiffusion2 fast(1e-10, 100), reference(1e-14, 1000);
    const LinearSolveReport r = fast.diffuseVelocity(grid, walls, nu, dt);
    EXPECT_TRUE(r.converged);
    EXPECT_LE(r.relative_residual, 1e-10);
    EXPECT_TRUE(reference.diffuseVelocity(tight, walls, nu, dt).converged);
    EXPECT_LE(maxAbsDifference(grid.u_m_per_s.data(), tight.u_m_per_s.data(), grid.u_m_per_s.size()), 1e-10 * b_norm)
        << "10 alpha = " << ten_alpha;
    EXPECT_LE(maxAbsDifference(grid.v_m_per_s.data(), tight.v_m_per_s.data(), grid.v_m_per_s.size()), 1e-10 * b_norm)
        << "10 alpha = " << ten_alpha;
  }
}

// Beyond the Richardson range and while α g ≤ kChebyshevSpread (g = 8 here: the 5-point
// stencil's Gershgorin row sum), Chebyshev's semi-iteration finishes the solve: it meets the
// tolerance it reports, agrees with the exact (fast direct) solution to that tolerance, and takes
// no more sweeps than its rate (√κ − 1)/(√κ + 1), κ = 1 + α g, allows: ‖r_k‖₂ ≤ 2 σ^k ‖r_0‖₂ with
// ‖r_0‖₂ ≤ √n (‖b‖∞ + (1 + 2 α g) ‖x^n‖∞). An unaccelerated (Richardson-rate) iteration would
// need about κ/2 · ln(1/tolerance) sweeps, 3–30 times the bound at these α.
TEST(Viscosity, ChebyshevSweepsMeetTheToleranceAtTheirRate) {
  const int nx = 40, ny = 30;
  const double dx = 0.01;
  const Walls walls = floor_and_moving_lid();
  for (double alpha : {0.05, 0.5, 5.0}) {
    SCOPED_TRACE(::testing::Message() << "alpha " << alpha);
    const double g = 8.0;
    ASSERT_GT(10.0 * alpha, ImplicitDiffusion2::kSweepContraction);
    ASSERT_LE(alpha * g, ImplicitDiffusion2::kChebyshevSpread);
    MacGrid2 grid = rough_vortex(nx, ny, dx, walls);
    const double x_norm = std::max(maxAbs(grid.u_m_per_s), maxAbs(grid.v_m_per_s));
    const double b_norm = x_norm + 2.0 * alpha * 0.05;
    MacGrid2 exact = grid;
    const double nu = 1e-3, dt = alpha * dx * dx / nu;
    const double tolerance = 1e-10;
    ImplicitDiffusion2 chebyshev(tolerance, 1000);
    const LinearSolveReport r = chebyshev.diffuseVelocity(grid, walls, nu, dt);
    EXPECT_TRUE(r.converged);
    EXPECT_LE(r.relative_residual, tolerance);
    ASSERT_TRUE(FastDiffusion2(1e-12).diffuseVelocity(exact, walls, nu, dt).converged);
    EXPECT_LE(maxAbsDifference(grid.u_m_per_s.data(), exact.u_m_per_s.data(), grid.u_m_per_s.size()),
              2 * tolerance * b_norm);
    EXPECT_LE(maxAbsDifference(grid.v_m_per_s.data(), exact.v_m_per_s.data(), grid.v_m_per_s.size()),
              2 * tolerance * b_norm);
    const double kappa = 1.0 + alpha * g;
    const double sigma = (std::sqrt(kappa) - 1.0) / (std::sqrt(kappa) + 1.0);
    const double r0 = std::sqrt(double(nx + 1) * ny) * (b_norm + (1.0 + 2.0 * alpha * g) * x_norm);
    const int bound = int(std::ceil(std::log(2.0 * r0 / (tolerance * b_norm)) / std::log(1.0 / sigma)));
    EXPECT_LE(r.iterations, bound + 1);  // + 1: the sweep that measures the accepted iterate
    EXPECT_GE(r.iterations, 2);
  }
}

// Couette flow: a moving top wall over a no-slip bottom, open at both ends. A backward-Euler
// step with a very long dt reaches the steady profile u = U y / H, which the ghost values
// represent exactly (either solver; the fast one through its dense transform along y).
TEST(Viscosity, LongImplicitStepGivesCouetteProfile) {
  const int nx = 8, ny = 10;
  const double dx = 0.1, top_speed = 0.7;
  const Walls walls = couette_walls(top_speed);
  for (auto& diffusion : viscosity_solvers(1e-14, 2000)) {
    MacGrid2 grid(nx, ny, dx);
    diffusion->diffuseVelocity(grid, walls, 1.0, 1e9);
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i <= nx; ++i) EXPECT_NEAR(grid.u_m_per_s(i, j), top_speed * (j + 0.5) / ny, 1e-6);
    }
    Array2 omega;
    vorticityAtCorners(grid, walls, omega);
    EXPECT_NEAR(omega(3, 0), -top_speed / (ny * dx), 1e-5);  // ω = −∂u/∂y
  }
}

TEST(Sampler, GhostsSetTheWallValue) {
  MacGrid2 grid(4, 4, 1.0);
  grid.u_m_per_s.fill(2.0);
  for (WallType type : {WallType::free_slip, WallType::no_slip, WallType::moving, WallType::open}) {
    Walls walls;
    walls.bottom.type = type;
    if (type == WallType::moving) walls.bottom.tangential_velocity_m_per_s = -1.5;
    StaggeredComponent2 u;
    u.assign(FaceAxis::x, grid.u_m_per_s, walls);
    const double at_wall = u.sample(2.0, 0.0);
    const double expected = type == WallType::no_slip ? 0.0 : type == WallType::moving ? -1.5 : 2.0;
    EXPECT_DOUBLE_EQ(at_wall, expected) << to_string(type);
    EXPECT_DOUBLE_EQ(u.sample(2.0, 0.5), 2.0);  // the first sample row
  }
}

// A linear velocity field (solid-body rotation) is interpolated exactly, its vorticity is 2Ω
// and RK2 tracers keep their radius.
TEST(Tracers, SolidBodyRotation) {
  const int n = 32;
  const double size = 1.0, omega = 2.0;
  MacGrid2 grid(n, n, size / n);
  const double c = 0.5 * size;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= n; ++i) grid.u_m_per_s(i, j) = -omega * (grid.uPosition_m(i, j).y - c);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i < n; ++i) grid.v_m_per_s(i, j) = omega * (grid.vPosition_m(i, j).x - c);
  Walls walls;
  for (Wall* w : {&walls.left, &walls.right, &walls.bottom, &walls.top}) w->type = WallType::open;
  VelocitySampler2 sampler;
  sampler.assign(grid, walls);
  const Vec2 u = sampler.velocityAt_m_per_s({0.3, 0.7});
  EXPECT_NEAR(u.x, -omega * 0.2, 1e-14);
  EXPECT_NEAR(u.y, omega * -0.2, 1e-14);

  Array2 vorticity;
  vorticityAtCorners(grid, walls, vorticity);
  EXPECT_NEAR(vorticity(10, 20), 2.0 * omega, 1e-12);

  std::vector<Vec2> tracers{{0.8, 0.5}, {0.5, 0.3}};
  const int steps = 200;
  const double dt = 2.0 * std::numbers::pi / omega / steps;
  for (int s = 0; s < steps; ++s) advectTracersRk2(tracers, sampler, dt, size, size);
  EXPECT_NEAR(tracers[0].x, 0.8, 1e-3);
  EXPECT_NEAR(tracers[0].y, 0.5, 1e-3);
  EXPECT_NEAR(std::hypot(tracers[1].x - c, tracers[1].y - c), 0.2, 1e-4);
}

TEST(Tracers, MoveExactlyWithUniformFlowAndStayInside) {
  FluidParams params = box(8, 1.0);
  for (Wall* w : {&params.walls.left, &params.walls.right, &params.walls.bottom, &params.walls.top}) {
    w->type = WallType::open;
  }
  FluidSolver2 solver(params);
  solver.grid().u_m_per_s.fill(0.5);
  solver.grid().v_m_per_s.fill(-0.25);
  solver.tracers_m() = {{0.25, 0.5}, {0.99, 0.01}};
  solver.stages() = FluidStages{false, false, false, false, true};
  solver.step(0.1);
  EXPECT_DOUBLE_EQ(solver.tracers_m()[0].x, 0.3);
  EXPECT_DOUBLE_EQ(solver.tracers_m()[0].y, 0.475);
  EXPECT_EQ(solver.tracers_m()[1].x, 1.0);  // clamped to the domain
  EXPECT_EQ(solver.tracers_m()[1].y, 0.0);
}

TEST(Diagnostics, KineticEnergyDivergenceAndCfl) {
  MacGrid2 grid(10, 5, 0.2);
  grid.u_m_per_s.fill(3.0);
  EXPECT_NEAR(kineticEnergy_joule_per_m(grid, 1000.0), 0.5 * 1000.0 * 9.0 * (2.0 * 1.0), 1e-9);
  EXPECT_EQ(maxDivergence_per_s(grid), 0.0);
  EXPECT_DOUBLE_EQ(cflNumber(grid, 0.1), 3.0 * 0.1 / 0.2);
  grid.v_m_per_s(4, 2) = 1.0;
  EXPECT_DOUBLE_EQ(maxDivergence_per_s(grid), 1.0 / 0.2);
  grid.u_m_per_s(3, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isinf(maxVelocityComponent_m_per_s(grid)));
  EXPECT_TRUE(std::isinf(summarizeFlow(grid, 1.0).max_velocity_component_m_per_s));
}

// The one-pass summary that step() reports equals the separate observables.
TEST(Diagnostics, SummaryAgreesWithTheSeparateFunctions) {
  MacGrid2 grid(13, 9, 0.05);
  setVortexPair(grid, VortexPair{});
  grid.v_m_per_s(4, 0) = 0.3;  // some divergence and a wall face
  const FlowSummary summary = summarizeFlow(grid, 998.0);
  EXPECT_EQ(summary.max_velocity_component_m_per_s, maxVelocityComponent_m_per_s(grid));
  EXPECT_EQ(summary.max_divergence_per_s, maxDivergence_per_s(grid));
  EXPECT_NEAR(summary.kinetic_energy_joule_per_m, kineticEnergy_joule_per_m(grid, 998.0),
              1e-14 * kineticEnergy_joule_per_m(grid, 998.0));
}

}  // namespace
}  // namespace creaturelab::fluid
