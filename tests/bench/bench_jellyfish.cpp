// Speed of the swimming jellyfish: simulated seconds per CPU second of the coupled bell + fluid step
// (Rudolf & Mould 2009 §4 report 30-40 frames/s on a 1.6 GHz laptop).
// Goal: >= 20 simulated s per CPU s on the paper's 100² grid on one core (BM_SimulatedSecond, Peskin's kernel).
// One iteration is one simulated second at the paper's step (0.01 s) after a one-cycle warm-up, with the paper's
// parameters at 0.7 Hz; the bilinear kernel's rows (peskin4:0) are marginal at this step and may stop with a
// crumpled bell. Reported as "sim_s_per_wall_s" (its historical name) per CPU second of the process, so that
// other processes on a shared machine do not inflate it, and as "sim_s_per_elapsed_s" per elapsed second.
#include <benchmark/benchmark.h>
#include <time.h>

#include <cmath>
#include <exception>
#include <memory>
#include <string>

#include "jellyfish/swimmer.hpp"
#include "kinds/jellyfish.hpp"

namespace creaturelab::jellyfish {
namespace {

double clockSeconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
// CPU time of all threads of the process (the fluid's workers included; with one fluid thread
// there are none and this is the thread's CPU time), and elapsed time.
double cpuSeconds() { return clockSeconds(CLOCK_PROCESS_CPUTIME_ID); }
double elapsedSeconds() { return clockSeconds(CLOCK_MONOTONIC); }

SwimmerConfig paperConfig(int cells, ib::Kernel kernel) {
  SwimmerConfig c = paperSwimmer();  // Fig. 12 bell at 0.7 Hz, staggered, 0.4 m box of sea water
  c.fluid.cells_x = c.fluid.cells_y = cells;
  c.fluid.time_step_policy = fluid::TimeStepPolicy::fixed;
  c.fluid.fixed_step_s = c.dt_s = 0.01;
  c.coupling.kernel = kernel;
  return c;
}

void measure(benchmark::State& state, const SwimmerConfig& config) {
  const long steps_per_second = std::lround(1.0 / config.dt_s);
  // A fresh swimmer every 10 simulated seconds (not timed): it swims away over longer runs.
  auto fresh = [&] {
    auto s = std::make_unique<Swimmer>(config);
    for (long k = 0; k < std::lround(1.0 / 0.7 / config.dt_s); ++k) s->step();  // warm-up cycle
    return s;
  };
  auto swimmer = fresh();
  double cpu = 0;
  double elapsed = 0;
  long seconds = 0;
  long viscosity_iterations = 0;
  for (auto _ : state) {
    if (seconds > 0 && seconds % 10 == 0) {
      state.PauseTiming();
      swimmer = fresh();
      state.ResumeTiming();
    }
    const double t0 = cpuSeconds();
    const double e0 = elapsedSeconds();
    try {
      for (long k = 0; k < steps_per_second; ++k) viscosity_iterations += swimmer->step().fluid.viscosity.iterations;
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    const double spent = cpuSeconds() - t0;
    elapsed += elapsedSeconds() - e0;
    state.SetIterationTime(spent);
    cpu += spent;
    ++seconds;
  }
  // "sim_s_per_wall_s" is per CPU second (its historical name); sim_s_per_elapsed_s is per
  // second of elapsed time, which threads shorten and other processes lengthen.
  state.counters["sim_s_per_wall_s"] = static_cast<double>(seconds) / cpu;
  state.counters["sim_s_per_elapsed_s"] = static_cast<double>(seconds) / elapsed;
  state.counters["fluid_threads"] = config.fluid.threads;
  state.counters["ms_per_step"] = 1e3 * cpu / static_cast<double>(seconds * steps_per_second);
  state.counters["markers"] = static_cast<double>(swimmer->markers_m().size());
  // The viscous solve's sweeps and iterations per step, of the worse of the two components.
  state.counters["viscosity_iterations"] = double(viscosity_iterations) / double(seconds * steps_per_second);
  const ib::ReusedBandedSolve& solver = swimmer->coupling().bandedSolver();
  if (solver.solves() > 0) {
    state.counters["factorizations_per_solve"] = double(solver.factorizations()) / double(solver.solves());
    state.counters["sweeps_per_solve"] = double(solver.sweeps()) / double(solver.solves());
  }
}

void BM_SimulatedSecond(benchmark::State& state) {
  const auto kernel = state.range(1) == 0 ? ib::Kernel::bilinear : ib::Kernel::peskin4;
  measure(state, paperConfig(static_cast<int>(state.range(0)), kernel));
}
BENCHMARK(BM_SimulatedSecond)
    ->ArgNames({"cells", "peskin4"})
    ->Args({50, 0})
    ->Args({100, 0})
    ->Args({50, 1})
    ->Args({100, 1})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

// The paper's grid with the fluid step shared by two threads (FluidParams::threads; bitwise the
// same swim): CPU time is that of both threads, elapsed time is what the threads shorten.
void BM_SimulatedSecondFluidThreads(benchmark::State& state) {
  SwimmerConfig c = paperConfig(static_cast<int>(state.range(0)), ib::Kernel::peskin4);
  c.fluid.threads = static_cast<int>(state.range(1));
  measure(state, c);
}
BENCHMARK(BM_SimulatedSecondFluidThreads)
    ->ArgNames({"cells", "threads"})
    ->Args({100, 2})
    ->Args({200, 2})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

// The grid study's bell (experiments/jellyfish/convergence_hat.toml): active tension (5 N/m²) on the
// calibrated bell (B = 1e-4 N m), ν = 1.304e-5 m²/s, MacCormack advection, a box 1.5 times as tall as wide,
// markers half a cell apart, dt ∝ dx, the kernel stretched to the bell's 4 mm thickness.
// Goal: a converged point (an 11 s point: 10 s window + a 0.7 Hz warm-up cycle) in <= 60 CPU s, i.e.
// >= 0.18 simulated s per CPU s. The second argument 1 runs the viscosity stage with the fast direct solver
// (fluid/fast_diffusion2.hpp; the same swim to the viscosity tolerance, not bitwise).
SwimmerConfig gridStudyConfig(int cells, ib::Kernel kernel, int kernel_scale, int segments) {
  SwimmerConfig c = paperConfig(cells, kernel);
  c.coupling.kernel_scale = kernel_scale;
  c.fluid.kinematic_viscosity_m2_per_s = 1.304e-5;
  c.bell.segments = segments;
  c.bell.muscle_model = MuscleModel::active_tension;
  c.bell.muscle_tension_n_per_m2 = 5.0;
  c.bell.bending_rigidity_n_m = 1.0e-4;
  c.fluid.advection = fluid::AdvectionScheme::maccormack;
  c.fluid.cells_y = cells * 3 / 2;
  c.fluid.domain_height_m = 1.5 * c.fluid.domain_width_m;
  c.start_y_fraction = 0.2;
  c.fluid.fixed_step_s = c.dt_s = 0.00125 * 200.0 / cells;
  return c;
}

void BM_SimulatedSecondGridStudy(benchmark::State& state) {
  const int cells = static_cast<int>(state.range(0));
  SwimmerConfig c = gridStudyConfig(cells, ib::Kernel::bilinear, cells / 100, cells * 64 / 200);
  if (state.range(1) == 1) c.fluid.viscosity_solver = fluid::ViscositySolverType::fast_direct;
  measure(state, c);
}
BENCHMARK(BM_SimulatedSecondGridStudy)
    ->ArgNames({"cells", "fast_viscosity"})
    ->ArgsProduct({{100, 200, 400}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(4.0);

// The grid study's bell with Peskin's 4-point function at the same 4 mm radius and 256 segments on every grid
// (419 markers with the tentacles: 838 unknowns in the semi-implicit system). Second argument: 0 the dense LU,
// 1 the banded one (ib/banded_lu.hpp; the same steps to round-off). One iteration is one simulated second.
void BM_SimulatedSecondPeskin256(benchmark::State& state) {
  const int cells = static_cast<int>(state.range(0));
  SwimmerConfig c = gridStudyConfig(cells, ib::Kernel::peskin4, cells / 200, 256);
  c.coupling.banded_solve = state.range(1) == 1;
  measure(state, c);
}
BENCHMARK(BM_SimulatedSecondPeskin256)
    ->ArgNames({"cells", "banded"})
    ->ArgsProduct({{200, 400}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(4.0);

// The converged study's bell: 256 segments, Peskin's function at the 4 mm radius, a 0.3 s pulse of 14 N/m²
// per cycle at 0.7 Hz, ν = 5e-5 m²/s, a 0.3 m by 0.45 m box (150 cells: 2 mm; 300: 1 mm), dt ∝ dx.
// Second argument: 0 factors the banded semi-implicit system every step; d refines on earlier factors
// (ib/reused_banded_solve.hpp) to a residual of 10^-d (8: the default). Goal: >= 0.18 simulated s per CPU s.
SwimmerConfig viscousPulseConfig(int cells) {
  SwimmerConfig c = gridStudyConfig(cells, ib::Kernel::peskin4, cells / 150, 256);
  c.fluid.domain_width_m = 0.3;
  c.fluid.domain_height_m = 0.45;
  c.fluid.kinematic_viscosity_m2_per_s = 5e-5;
  c.bell.muscle_tension_n_per_m2 = 14.0;
  c.activation.shape = ActivationShape::pulse;
  c.activation.pulse_duration_s = 0.3;
  c.fluid.fixed_step_s = c.dt_s = 0.1875 / cells;
  return c;
}

void BM_SimulatedSecondViscousPulse(benchmark::State& state) {
  SwimmerConfig c = viscousPulseConfig(static_cast<int>(state.range(0)));
  c.coupling.factor_reuse.tolerance = state.range(1) == 0 ? 0.0 : std::pow(10.0, -double(state.range(1)));
  measure(state, c);
}
BENCHMARK(BM_SimulatedSecondViscousPulse)
    ->ArgNames({"cells", "reuse_digits"})
    ->ArgsProduct({{150, 300}, {0, 8}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// The jellyfish kind's default point as the runner builds it (kinds::JellyfishKindParams' defaults: its grid,
// step, box, filament tentacles and drive), so that the row follows the default. Goal: a whole
// default point, one warm-up cycle and a 10 s swim at 0.7 Hz (11.43 simulated s), in <= 60 CPU s, i.e.
// >= 0.19 simulated s per CPU s (sim_s_per_wall_s).
void BM_KindDefaultPoint(benchmark::State& state) {
  kinds::JellyfishKindParams params;
  if (std::string e = params.validate(); !e.empty()) {
    state.SkipWithError(e.c_str());
    return;
  }
  measure(state, params.setup());
}
BENCHMARK(BM_KindDefaultPoint)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace creaturelab::jellyfish
