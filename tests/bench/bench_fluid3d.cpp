// Speed of the 3-D fluid solver: one full step at 32³ and 64³, reported as milliseconds of CPU time
// per step ("ms_per_step", all the process's threads) and per cell ("ns_per_cell"), with the elapsed
// time ("ms_per_step_wall") and the pressure solve's iterations. Scenes: the flyer's box (water, no-slip
// walls, an open top; MG-PCG; MacCormack, and at one thread the other two advection schemes) and the periodic ABC flow (spectral and MG-PCG), at 1 and 2 threads
// (bitwise the same results). Figures from different hosts or hours compare only against a build run
// beside them.
#include <benchmark/benchmark.h>
#include <time.h>

#include <memory>
#include <numbers>

#include "fluid3d/fluid_solver3.hpp"
#include "fluid3d/initial_conditions3.hpp"

namespace creaturelab::fluid3d {
namespace {

double clockSeconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

enum class Scene { open_box, periodic };

std::unique_ptr<FluidSolver3> warmedUp(Scene scene, int cells, PressureSolverType3 pressure, int threads,
                                       AdvectionScheme3 advection) {
  FluidParams3 p;  // 0.4 m box of water
  p.advection = advection;
  p.cells_x = p.cells_y = p.cells_z = cells;
  p.pressure_solver = pressure;
  p.threads = threads;
  p.pressure_tolerance = 1e-8;
  if (scene == Scene::open_box) {
    p.boundaries = Boundaries3::allWalls(BoundaryType3::no_slip);
    p.boundaries.axis[2].high = BoundaryType3::open;
  } else {
    p.boundaries = Boundaries3::allPeriodic();
  }
  auto solver = std::make_unique<FluidSolver3>(p);
  AbcFlow flow;
  flow.a_m_per_s = 0.02, flow.b_m_per_s = 0.015, flow.c_m_per_s = 0.01;
  flow.wavenumber_per_m = 2 * std::numbers::pi / p.domain_x_m;
  setAbcFlow(solver->grid(), flow, 0.0);
  solver->makeDivergenceFree();
  for (int s = 0; s < 3; ++s) solver->step();
  return solver;
}

void stepBenchmark(benchmark::State& state, Scene scene, PressureSolverType3 pressure,
                   AdvectionScheme3 advection = AdvectionScheme3::maccormack) {
  const int cells = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  auto solver = warmedUp(scene, cells, pressure, threads, advection);
  double cpu = 0.0, wall = 0.0;
  long iterations = 0;
  for (auto _ : state) {
    const double cpu0 = clockSeconds(CLOCK_PROCESS_CPUTIME_ID), wall0 = clockSeconds(CLOCK_MONOTONIC);
    const FluidStepReport3 report = solver->step();
    cpu += clockSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
    wall += clockSeconds(CLOCK_MONOTONIC) - wall0;
    iterations += report.pressure.iterations;
    state.SetIterationTime(clockSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["ms_per_step"] = 1e3 * cpu / n;
  state.counters["ms_per_step_wall"] = 1e3 * wall / n;
  state.counters["ns_per_cell"] = 1e9 * cpu / (n * static_cast<double>(cells) * cells * cells);
  state.counters["pressure_iterations"] = static_cast<double>(iterations) / n;
}

void BM_Step3_OpenBox_MgPcg(benchmark::State& state) {
  stepBenchmark(state, Scene::open_box, PressureSolverType3::mg_pcg);
}
void BM_Step3_OpenBox_MgPcg_Upwind(benchmark::State& state) {
  stepBenchmark(state, Scene::open_box, PressureSolverType3::mg_pcg, AdvectionScheme3::upwind2_rk2);
}
void BM_Step3_OpenBox_MgPcg_SemiLagrangian(benchmark::State& state) {
  stepBenchmark(state, Scene::open_box, PressureSolverType3::mg_pcg, AdvectionScheme3::semi_lagrangian);
}
void BM_Step3_Periodic_MgPcg(benchmark::State& state) {
  stepBenchmark(state, Scene::periodic, PressureSolverType3::mg_pcg);
}
void BM_Step3_Periodic_Spectral(benchmark::State& state) {
  stepBenchmark(state, Scene::periodic, PressureSolverType3::spectral);
}

BENCHMARK(BM_Step3_OpenBox_MgPcg)->ArgsProduct({{32, 64}, {1, 2}})->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step3_OpenBox_MgPcg_Upwind)->ArgsProduct({{32, 64}, {1}})->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step3_OpenBox_MgPcg_SemiLagrangian)
    ->ArgsProduct({{32, 64}, {1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step3_Periodic_MgPcg)->ArgsProduct({{32, 64}, {1, 2}})->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step3_Periodic_Spectral)->ArgsProduct({{32, 64}, {1, 2}})->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace creaturelab::fluid3d
