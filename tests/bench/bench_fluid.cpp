// Speed of the fluid solver (issue 4): one full step and the pressure solve alone at 64²..512²,
// reported as ns per cell per step ("ns_per_cell"). Goals: a full step at 128² in ≤ 0.5 ms on
// one core; issue 13 §4: ≤ 20 ns per cell per step at 256². The scene is the paper's: water in
// a free-slip box, a vortex pair moving through it. Times are CPU time (manual timing) of all
// the process's threads, so that other processes on a shared machine do not inflate them; the
// full steps also report elapsed time per cell ("ns_per_cell_wall"), and run at 1 and 2
// threads (FluidParams::threads; bitwise the same results).
//
// Measured 2026-11-24 on the shared 2-core machine (load average 5-9 from other work: treat the
// figures as upper bounds), minimum over 3 repetitions, twice, interleaved with the build before
// issue 13 §4; before -> after:
//   1 thread, CPU ns per cell        128²          256²
//     semi-Lagrangian              36.5 -> 33     52 -> 38.6
//     MacCormack                   58.5 -> 51     79.5 -> 58.6
// Stage by stage at 256², MacCormack, 1 thread: advection 36 (six bilinear samples per face),
// viscosity 8 (four Richardson sweeps), pressure 12, forces and diagnostics 3. The 20 ns goal is
// not met on one core. With 2 threads on this loaded machine the step is slower than with one
// (at load 9: CPU 47-75, elapsed 62-99 ns per cell, against 1 thread's 33-59 CPU, 47-82
// elapsed): the workers wait for a core; what the threads gain on an idle machine is not
// measured here.
//
// Eulerian advection option (AdvectionScheme::upwind2_rk2, fluid/upwind_advection2.hpp),
// measured 2026-11-25 on the same machine (load 4.5-9), minimum of 3 repetitions, 1 thread,
// CPU ns per cell, 128² / 256²:
//   full step   semi-Lagrangian 33.3 / 39.3, MacCormack 51.9 / 60.7, upwind2_rk2 25.5 / 30.6
//   advection   semi-Lagrangian 15.5 / 16.4, MacCormack 33.4 / 36.4, upwind2_rk2  7.4 /  9.0
//   viscosity 5.0 / 6.0, pressure (fast direct) 9.7 / 11.8 (BM_Advection_*, BM_Viscosity,
//   BM_Pressure_FastDirect). With upwind2_rk2 the 256² step is 9 + 6 + 12 + 3-4 (forces,
//   diagnostics, copies): the 20 ns goal still needs about 10 ns from viscosity and pressure.
// Where the rest could come from (measured the same day, 256², not implemented): the viscosity
// stage costs about 1.6 ns fixed plus 1.3 ns per Richardson sweep; at the jellyfish's dt
// (1.25 ms, α = 6.7e-4) it already takes 2 sweeps (4.3 ns), at the bench's dt (10 ms) 3 (5.5
// ns), so faster-contracting sweeps (red–black Gauss–Seidel) save at most about 1.3 ns. The
// projection is ~2/3 transforms (perf: fft 38 %, forward/inverse_transform 24 %, Thomas 10 %,
// divergence and gradient 13 %), about 8 ns; FFTW 3.3.10 (REDFT10 + REDFT01 over all 256
// lines, FFTW_ESTIMATE) takes 5.2 ns for both, so FFTW would save about 3 ns. Both together
// bring the upwind2_rk2 step to about 26 ns, still above 20 on one core.
//
// Issue 13 §4, measured 2026-11-25 (speed13 branch), 256², upwind2_rk2 + fast direct pressure +
// iterative viscosity: the best configuration. Its bench row is
// BM_FluidStep_Upwind2Rk2_FastPressure/cells:256/threads:1 and /threads:2. Minimum of 5
// repetitions at load average 10.8-12.1 (07:38-07:41 UTC; other sessions' simulations held
// the 2 cores), ns per cell, CPU of all threads / elapsed:
//                                    1 thread        2 threads
//   full step                        30.3 / 58.6     42.6 / 66.5
//   advection (upwind2_rk2)           8.8 / 16.9     10.2 / 17.0
//   viscosity (iterative, 3 sweeps)   5.8 / 11.8      6.7 / 13.3
//   projection (fast direct)         12.0 / 23.6     19.4 / 31.3
// (An earlier run the same morning at load 5: full step 29.3 CPU, 39.0 elapsed with 1 thread,
// 39.8 / 50.8 with 2; advection 8.6, viscosity 5.8, projection 11.3.) The rest of the step,
// about 3.8 ns, is the forces, the start-of-step maximum speed and the end-of-step summary.
// On that loaded machine the goal (≤ 20 ns per cell) was not met: 30.3 CPU on one core, and with
// two threads 66.5 elapsed (the workers wait for a core).
//
// On idle cores (2026-11-25, 09:47-09:50 UTC, no other process running; medians of 5
// repetitions, two interleaved runs), after the fast pressure solver's FFT moved into one panel
// of arrays per thread (fast_pressure_solver2.hpp: two threads transforming the two halves of
// shared rows had been no faster than one), ns per cell, 256², upwind2_rk2 + fast pressure:
//                                    1 thread (CPU = elapsed)   2 threads, elapsed (CPU)
//   full step                        28.1-29.4                  19.4-19.8 (38.7-39.4)
//   projection (fast direct)          9.8-10.3                   6.6-7.7
//   advection (upwind2_rk2)           9.1                        5.2-6.0
//   viscosity (iterative)             5.9-6.1                    4.2-4.7
// Before the panels the 2-thread step took 25.6 (projection 13.9). Again at 11:16 UTC on an idle
// machine (load average 0.03, nothing stopped or running beside it), medians of 5, twice: 1 thread
// 27.4 / 28.2, 2 threads 18.3 / 19.0 elapsed (CPU 36.6 / 38.1); at 10:36, between other jobs
// stopped with SIGSTOP, 30.8 and 20.6-20.9. The goal is met on two threads (18.3-19.8 elapsed on
// idle cores, a margin of 1-9%), not on one core.
// 2026-11-29 13:11 UTC, idle machine, two runs, 256², elapsed ns per cell: semi-Lagrangian 58.2-58.5
// on 1 thread, 33.9-43.3 on 2; MacCormack 76.5-83.0 on 1, 39.1-52.6 on 2. The same hour the 2026-11-25 build ran the 100² swim about 1.5 times slower
// than it did then (bench_jellyfish.cpp): today's host is slower, so the goal is not met here on
// either thread count, and figures from different days compare only against a build run beside them.
// 2026-12-01 19:45 UTC, idle machine, minimum of 3 repetitions, two interleaved runs of the build
// before AVX2 (45fe289) and after it (CREATURELAB_AVX2, CMakeLists.txt: the fluid library built with
// AVX2, its sampling four lanes wide with the same per-lane arithmetic; datasets bitwise the same),
// 256², CPU ns per cell, before -> after:
//                              1 thread                 2 threads (elapsed)
//   semi-Lagrangian step       27.7-28.3 -> 21.8-22.2    13.8-22.5 -> 11.2-11.5
//   MacCormack step            41.2-44.5 -> 32.7         22.3-29.2 -> 17.0-17.8
//   upwind2_rk2 step           20.4-21.4 -> 15.5-15.6    11.8      ->  8.4-8.6
//   advection SL / MacCormack  11.7-12.3 / 24.9-26.6 -> 9.0-9.2 / 18.5-20.8
//   viscosity, pressure        4.4-4.6, 6.9 -> 4.1-4.3, 4.9-5.1
// So on this host issue 13's 20 ns per cell is met on one core by upwind2_rk2 (15.5) and on two
// threads by every scheme (MacCormack 17.0-17.8 elapsed), not by semi-Lagrangian (21.8-22.2) or
// MacCormack (32.7) on one core.
// 2026-12-02 00:50 UTC, idle machine, minimum of 3 repetitions, two interleaved runs of the build
// before (31dd5d3) and after Chebyshev's semi-iteration (fluid/diffusion2.hpp: it replaces CG for
// α g ≤ 64, and the sweeps, Richardson's included, run four lanes wide with the same arithmetic),
// 256², 1 thread, CPU ns per cell, before -> after:
//   viscosity, water (3 Richardson sweeps, bitwise the same)    4.81-4.91 -> 3.74-3.83
//   viscosity, BM_Viscosity_Viscous (α = 0.53)                 38.5-40.3 (CG, 17) -> 28.4-29.1 (22 sweeps)
//   MacCormack step                                            37.9-38.5 -> 33.7-35.4
// At 10 and 100 times BM_Viscosity_Viscous's ν (α g = 42 and 424) Chebyshev took 90.6 and 300 ns per
// cell against CG's 151 and 479 (69 / 62 and 231 / 214 iterations); CG stays the solver beyond
// α g = 64 for small grids, where it ends in at most n iterations.
// 2026-12-04 20:10 UTC, idle machine, minimum of 3 repetitions, two interleaved runs of the build
// before (4231d59) and after the sampler's contiguous loads (fluid/staggered_sampler2.hpp: four
// neighbouring stencils in a row, the usual case, are read with four loads instead of eight half-loads
// and a transpose; the same values, datasets bitwise the same), 256², µs per step (ns per cell):
//                              1 thread                                2 threads (elapsed)
//   MacCormack step            4112 / 4051 -> 3452 / 3408 (62.3 -> 52.3)   4748 / 5095 -> 4460 / 4339
//   semi-Lagrangian step       2833 / 2784 -> 2480 / 2372 (42.9 -> 37.0)   3429 / 3452 -> 3260 / 3220
// (-16% and -13% on one thread). This host was slow (the paper's grid 15.9-16.3 simulated s per CPU s
// against 22.5-22.7 on the host of that morning) and ran two threads slower than one.
// 2026-12-04 23:40 and 2026-12-05 01:04 UTC, idle machine, medians of 3, 256², ns per cell, 1 thread CPU / 2
// threads elapsed: MacCormack 43.1 / 27.5 and 44.0 / 27.0, semi-Lagrangian 30.1 / 20.2 and 30.3 / 20.0,
// upwind2_rk2 27.2 / 16.4 and 24.5 / 17.8; stages at 23:40 (1 thread / 2 threads elapsed): advection
// MacCormack 26.5 / 15.1, semi-Lagrangian 12.1 / 7.7, upwind2_rk2 7.6 / 4.7, viscosity 5.5 / 4.0, pressure
// 9.9 / 7.2. The host ran the paper's 100² grid at 19.2 and then 20.5-21.8 simulated s per CPU s. The goal
// (20) held on two threads for upwind2_rk2 and, at the limit, semi-Lagrangian; MacCormack, the jellyfish's
// default, stayed at 27 on two threads and 43-44 on one.
// 2026-12-05 02:10-02:20 UTC, idle machine but a slower hour (the paper's grid at 16.5-17.2 simulated s per
// CPU s), two interleaved runs of the build before and after the sampler's truncation by rounding in place
// (staggered_sampler2.hpp, sample4_shifted: vroundpd instead of a conversion to integers and back; the same
// whole numbers, datasets bitwise the same), medians, 256², ns per cell, before -> after:
//   advection, 1 thread CPU         MacCormack 27.9 / 29.0 -> 25.7 / 25.5, semi-Lagrangian 12.8 / 13.3 -> 11.6 / 12.0
//   full step, 1 thread CPU         MacCormack 51.2 / 50.1 -> 49.7 / 48.5, semi-Lagrangian 37.2 / 36.3 -> 35.9 / 33.4
//   full step, 2 threads elapsed    MacCormack 37.3 / 32.0 -> 36.7 / 30.6, semi-Lagrangian 29.3 / 23.3 -> 28.9 / 21.9,
//                                   upwind2_rk2 21.5 / 18.5 -> 20.5 / 19.0
// (-8 to -12% on the sampling passes, -3% on a MacCormack step). MacCormack stays far from 20 on this host.
// 2026-12-05 06:00 UTC, idle machine, medians of 3, two interleaved runs of the build before (448083c) and
// after AVX-512F in the fluid library (CREATURELAB_AVX512, CMakeLists.txt: the sampler eight lanes wide with
// the four-lane arithmetic per lane, the compiler's element-wise loops eight wide; datasets bitwise the
// same), 256², ns per cell, before -> after:
//   MacCormack step           1 thread 59.2 / 50.0 -> 40.7 / 40.2, 2 threads (elapsed) 30.7 / 34.3 -> 27.1 / 26.6
//   semi-Lagrangian step      1 thread 35.2 / 35.3 -> 29.9 / 30.4, 2 threads (elapsed) 22.9 / 23.0 -> 21.5 / 21.6
//   upwind2_rk2 step          1 thread 29.4 / 29.4 -> 27.6 / 28.7, 2 threads (elapsed) 19.1 / 19.0 -> 18.5 / 18.6
//   MacCormack advection      25.3 / 25.3 -> 19.7 / 19.1;  pressure (fast direct) 12.3 / 12.3 -> 10.2 / 10.1
// The build of issue 13's baseline (f3030b5) ran this hour's MacCormack step at 101.5-102.1 (1 thread)
// where the issue measured 57-79: this host is 1.3-1.8 times slower than that one.
// 2026-12-05 06:35-06:48 UTC, idle machine, medians of 3, three interleaved runs of 448083c and of the
// build after the rest of that morning's changes (each thread runs its own parts first, worker_pool.hpp;
// the advection's padded copies shared among threads; two radix-2 FFT stages per pass; the odd radices
// eight lanes wide; all datasets bitwise the same), 256², ns per cell, before -> after:
//   MacCormack step        1 thread 50.7 / 51.2 / 51.1 -> 38.8 / 40.0 / 39.5
//                          2 threads (elapsed) 37.0 / 31.2 / 33.2 -> 21.8 / 21.4 / 21.8
//   semi-Lagrangian step   1 thread 35.8 / 35.8 / 39.2 -> 28.0 / 29.7 / 28.5
//                          2 threads 24.5 / 24.4 / 28.5 -> 15.6 / 20.3 / 15.8
//   upwind2_rk2 step       1 thread 29.7 / 29.3 / 30.2 -> 25.7 / 25.8 / 25.7
//                          2 threads 20.6 / 19.2 / 26.8 -> 14.4 / 17.9 / 14.5
//   stages, 1 thread       MacCormack advection 25.8 / 25.4 / 27.0 -> 19.4 / 24.2 / 18.9, pressure 12.4 / 12.0 /
//                          12.0 -> 8.7 / 8.9 / 8.8, viscosity 6.5 / 6.3 / 7.1 -> 6.4 / 6.8 / 6.3
// At 06:47, interleaved with f3030b5 (issue 13's baseline build): MacCormack 104.6-105.9 there against
// 38.1-39.5 (1 thread) and 41.7-44.3 of CPU (2 threads; their elapsed time was not recorded in this run: half
// the CPU is 20.8-22.2, and 21.4-21.8 elapsed was measured at 06:35) here; semi-Lagrangian 70.9-72.9 against
// 27.5-28.5 and 30.0-30.8 of CPU (half: 15.0-15.4). The issue measured the baseline at 57-79 and 36-50:
// scaled by those ratios the MacCormack step is 11-17 ns per cell on two threads (20.6-29.6 on one) and
// semi-Lagrangian 7-11 (14-20). On this host the goal (20) is met on two threads by semi-Lagrangian and
// upwind2_rk2, not by MacCormack (21-22).
//
// The fast direct viscosity option (FluidParams::viscosity_solver = fast_direct,
// fluid/fast_diffusion2.hpp; BM_Viscosity_FastDirect, BM_Viscosity_Viscous[_FastDirect]) is
// slower for water: 23.3 ns per cell at 256² against the iterative 5.8 (two DCT-solves per step,
// each about a projection's transforms, against 3 Richardson sweeps), and the full step with it
// 52.6 against 30.3. It pays for viscous flows: at ν = 100 × water (α = 0.53, CG takes 17
// iterations) 23.6 against 51.3 at 256² (22.1 against 24.6 at 100², load 5). The grid study
// (bench_jellyfish) is slower with it as well: 200², 6.17 against 4.63 ms per step; 400², 33.2
// against 26.7.
// FFTW (not used): 5.2 ns for both transforms at 256² (measured before) against about 7.7 here
// would save ~2.5 ns, not enough for 20 on one core; its plans for a share of the lanes (threads)
// may choose other codelets than for all lanes, which would break the bitwise equality across
// thread counts.
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
  set_vortex_pair(solver->grid(), pair);
  solver->make_divergence_free();
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
// previous pressure as warm start), the stage-by-stage figures of the header. The second
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
  const StepContext context{solver->steps_done(), solver->time_s(), solver->next_time_step_s()};
  solver->apply_external_forces(context);
  if (stage != Stage::advection) solver->advect_velocity(context);
  if (stage == Stage::pressure) solver->apply_viscosity(context);
  const MacGrid2 before = solver->grid();
  int iterations = 0;
  time_per_cell(state, cells, [&] { solver->grid() = before; }, [&] {
    if (stage == Stage::advection) {
      solver->advect_velocity(context);
    } else if (stage == Stage::viscosity) {
      iterations = solver->apply_viscosity(context).iterations;
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
