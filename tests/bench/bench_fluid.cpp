// Speed of the fluid solver: one full step and each stage alone at 64²..512², reported as ns per
// cell per step ("ns_per_cell"). Goals: a full step at 128² in <= 0.5 ms on one core; <= 20 ns per
// cell per step at 256². The scene is the paper's: water in a free-slip box, a vortex pair moving
// through it. Times are CPU time (manual timing) of all the process's threads, so that other
// processes on a shared machine do not inflate them; the full steps also report elapsed time per
// cell ("ns_per_cell_wall"), and run at 1 and 2 threads (FluidParams::threads; bitwise the same
// results). Figures from different hosts or hours compare only against a build run beside them.
// The fast direct viscosity option (FluidParams::viscosity_solver = fast_direct,
// fluid/fast_diffusion2.hpp; BM_Viscosity_FastDirect, BM_Viscosity_Viscous[_FastDirect]) pays only
// for viscous flows, where the iterative solve needs many sweeps.
#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "fluid/fast_pressure_solver2.hpp"
#include "fluid/fluid_solver2.hpp"
#include "fluid/initial_conditions2.hpp"
#include "fluid/pcg_pressure_solver2.hpp"

namespace creaturelab::fluid {
namespace {

double clock_seconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
// CPU time of all the process's threads (the solver's workers included; with one thread the
// solver has none, and this is the thread's CPU time), and elapsed time.
double cpu_seconds() { return clock_seconds(CLOCK_PROCESS_CPUTIME_ID); }
double wall_seconds() { return clock_seconds(CLOCK_MONOTONIC); }

FluidParams scene(int cells, AdvectionScheme scheme, PressureSolverType pressure, int threads = 1,
                  ViscositySolverType viscosity = ViscositySolverType::iterative) {
  FluidParams params;  // defaults: 0.4 m free-slip box of water
  params.cells_x = params.cells_y = cells;
  params.advection = scheme;
  params.pressure_solver = pressure;
  params.threads = threads;
  params.viscosity_solver = viscosity;
  return params;
}

std::unique_ptr<FluidSolver2> warmed_up(const FluidParams& params) {
  auto solver = std::make_unique<FluidSolver2>(params);
  VortexPair pair;
  pair.circulation_m2_per_s = 2e-3;
  setVortexPair(solver->grid(), pair);
  solver->makeDivergenceFree();
  for (int s = 0; s < 3; ++s) solver->step();
  return solver;
}

void report(benchmark::State& state, int cells, double seconds_total) {
  const double cell_count = static_cast<double>(cells) * cells;
  state.counters["ns_per_cell"] = seconds_total * 1e9 / (cell_count * static_cast<double>(state.iterations()));
  state.counters["cells"] = cell_count;
}

// report() from CPU time, and the elapsed time per cell (ns_per_cell_wall).
void report(benchmark::State& state, int cells, double cpu_total, double wall_total) {
  report(state, cells, cpu_total);
  state.counters["ns_per_cell_wall"] =
      wall_total * 1e9 / (static_cast<double>(cells) * cells * static_cast<double>(state.iterations()));
}

// Runs body() once per benchmark iteration after an untimed prepare(). Manual time = CPU time of
// all threads; the counters give it per cell (ns_per_cell) and the elapsed time per cell
// (ns_per_cell_wall), which is what threads shorten.
template <class Prepare, class Body>
void time_per_cell(benchmark::State& state, int cells, Prepare&& prepare, Body&& body) {
  double cpu_total = 0.0;
  double wall_total = 0.0;
  for (auto _ : state) {
    prepare();
    const double cpu0 = cpu_seconds();
    const double wall0 = wall_seconds();
    body();
    const double wall = wall_seconds() - wall0;
    const double cpu = cpu_seconds() - cpu0;
    state.SetIterationTime(cpu);
    cpu_total += cpu;
    wall_total += wall;
  }
  report(state, cells, cpu_total, wall_total);
}

// One full step per iteration, timed by time_per_cell.
// With threads_arg, the benchmark's second argument is FluidParams::threads.
void full_step(benchmark::State& state, AdvectionScheme scheme, PressureSolverType pressure, bool threads_arg = true,
               ViscositySolverType viscosity = ViscositySolverType::iterative) {
  const int cells = static_cast<int>(state.range(0));
  const int threads = threads_arg ? static_cast<int>(state.range(1)) : 1;
  auto solver = warmed_up(scene(cells, scheme, pressure, threads, viscosity));
  time_per_cell(state, cells, [] {}, [&] {
    FluidStepReport r = solver->step();
    benchmark::DoNotOptimize(r);
  });
  state.counters["threads"] = threads;
}

// One stage alone on the state just before it (the grid restored every iteration, untimed):
// advection (per scheme), viscosity (either solver, water or another ν) and the projection
// (a realistic right-hand side: the velocity of the next step just before its projection, the
// previous pressure as warm start). The second
// argument is FluidParams::threads; like full_step, CPU time of all threads per cell
// (ns_per_cell) and elapsed time per cell (ns_per_cell_wall).
enum class Stage { advection, viscosity, pressure };
struct StageSetup {
  AdvectionScheme scheme = AdvectionScheme::semi_lagrangian;
  PressureSolverType pressure = PressureSolverType::fast_direct;
  ViscositySolverType viscosity = ViscositySolverType::iterative;
  double nu_m2_per_s = 0.0;  ///< 0: water (the default)
};
void stage_only(benchmark::State& state, Stage stage, const StageSetup& setup) {
  const int cells = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  FluidParams params = scene(cells, setup.scheme, setup.pressure, threads, setup.viscosity);
  if (setup.nu_m2_per_s > 0.0) params.kinematic_viscosity_m2_per_s = setup.nu_m2_per_s;
  auto solver = warmed_up(params);
  const StepContext context{solver->stepsDone(), solver->time_s(), solver->nextTimeStep_s()};
  solver->applyExternalForces(context);
  if (stage != Stage::advection) solver->advectVelocity(context);
  if (stage == Stage::pressure) solver->applyViscosity(context);
  const MacGrid2 before = solver->grid();
  int iterations = 0;
  time_per_cell(state, cells, [&] { solver->grid() = before; }, [&] {
    if (stage == Stage::advection) {
      solver->advectVelocity(context);
    } else if (stage == Stage::viscosity) {
      iterations = solver->applyViscosity(context).iterations;
    } else {
      iterations = solver->project(context).iterations;
    }
  });
  state.counters["iterations"] = iterations;
}
void BM_Advection_SemiLagrangian(benchmark::State& state) {
  stage_only(state, Stage::advection, {AdvectionScheme::semi_lagrangian});
}
void BM_Advection_MacCormack(benchmark::State& state) {
  stage_only(state, Stage::advection, {AdvectionScheme::maccormack});
}
void BM_Advection_Upwind2Rk2(benchmark::State& state) {
  stage_only(state, Stage::advection, {AdvectionScheme::upwind2_rk2});
}
void BM_Viscosity(benchmark::State& state) { stage_only(state, Stage::viscosity, {}); }
void BM_Viscosity_FastDirect(benchmark::State& state) {
  stage_only(state, Stage::viscosity, {.viscosity = ViscositySolverType::fast_direct});
}
// A fluid 100 times as viscous as water (ν = 1.3e-4 m²/s, α = ν dt / dx² = 0.53 at 256² and the
// bench's dt of 10 ms): beyond the Richardson range, CG.
constexpr double kViscousNu = 1.304e-4;
void BM_Viscosity_Viscous(benchmark::State& state) {
  stage_only(state, Stage::viscosity, {.nu_m2_per_s = kViscousNu});
}
void BM_Viscosity_Viscous_FastDirect(benchmark::State& state) {
  stage_only(state, Stage::viscosity, {.viscosity = ViscositySolverType::fast_direct, .nu_m2_per_s = kViscousNu});
}

void BM_FluidStep_SemiLagrangian_FastPressure(benchmark::State& state) {
  full_step(state, AdvectionScheme::semi_lagrangian, PressureSolverType::fast_direct);
}
void BM_FluidStep_MacCormack_FastPressure(benchmark::State& state) {
  full_step(state, AdvectionScheme::maccormack, PressureSolverType::fast_direct);
}
void BM_FluidStep_Upwind2Rk2_FastPressure(benchmark::State& state) {
  full_step(state, AdvectionScheme::upwind2_rk2, PressureSolverType::fast_direct);
}
void BM_FluidStep_Upwind2Rk2_FastPressure_FastViscosity(benchmark::State& state) {
  full_step(state, AdvectionScheme::upwind2_rk2, PressureSolverType::fast_direct, true,
            ViscositySolverType::fast_direct);
}
void BM_FluidStep_SemiLagrangian_Pcg(benchmark::State& state) {
  full_step(state, AdvectionScheme::semi_lagrangian, PressureSolverType::pcg, false);
}
void BM_Pressure_FastDirect(benchmark::State& state) { stage_only(state, Stage::pressure, {}); }
void BM_Pressure_Pcg(benchmark::State& state) {
  stage_only(state, Stage::pressure, {.pressure = PressureSolverType::pcg});
}

// Besides mean and median, the minimum over repetitions: the least disturbed measurement.
double minimum(const std::vector<double>& values) { return *std::min_element(values.begin(), values.end()); }
// Sizes 64² … 512², plus 100², the paper's grid (Fig. 12), whose transform uses radix 5.
#define CL_FLUID_BENCH(name)          \
  BENCHMARK(name)                     \
      ->Arg(100)                      \
      ->RangeMultiplier(2)            \
      ->Range(64, 512)                \
      ->UseManualTime()               \
      ->Unit(benchmark::kMicrosecond) \
      ->ComputeStatistics("min", minimum)
// Full steps and stages alone at 1 and 2 threads (FluidParams::threads; the results are bitwise
// the same).
#define CL_FLUID_THREADS_BENCH(name)                                                     \
  BENCHMARK(name)                                                                        \
      ->ArgNames({"cells", "threads"})                                                   \
      ->ArgsProduct({{64, 100, 128, 256, 512}, {1, 2}})                                  \
      ->UseManualTime()                                                                  \
      ->Unit(benchmark::kMicrosecond)                                                    \
      ->ComputeStatistics("min", minimum)

CL_FLUID_THREADS_BENCH(BM_FluidStep_SemiLagrangian_FastPressure);
CL_FLUID_THREADS_BENCH(BM_FluidStep_MacCormack_FastPressure);
CL_FLUID_THREADS_BENCH(BM_FluidStep_Upwind2Rk2_FastPressure);
CL_FLUID_THREADS_BENCH(BM_FluidStep_Upwind2Rk2_FastPressure_FastViscosity);
CL_FLUID_BENCH(BM_FluidStep_SemiLagrangian_Pcg);
CL_FLUID_THREADS_BENCH(BM_Advection_SemiLagrangian);
CL_FLUID_THREADS_BENCH(BM_Advection_MacCormack);
CL_FLUID_THREADS_BENCH(BM_Advection_Upwind2Rk2);
CL_FLUID_THREADS_BENCH(BM_Viscosity);
CL_FLUID_THREADS_BENCH(BM_Viscosity_FastDirect);
CL_FLUID_THREADS_BENCH(BM_Viscosity_Viscous);
CL_FLUID_THREADS_BENCH(BM_Viscosity_Viscous_FastDirect);
CL_FLUID_THREADS_BENCH(BM_Pressure_FastDirect);
CL_FLUID_THREADS_BENCH(BM_Pressure_Pcg);

}  // namespace
}  // namespace creaturelab::fluid
