// Spring engine speed on a web-sized network: 7,000 particles, 10,000 springs (thesis §5.1: about
// 5,000 particles of 10 ug; k = 0.01 N/m; drag 1e-8 N s/m), 3D, under gravity.
// Goal (Release, one core): 10 simulated seconds with symplectic Euler at its automatic stable
// step in at most 1.5 s of wall time (BM_Simulate10sSymplecticAuto).
#include <benchmark/benchmark.h>

#include <memory>

#include "springs/integrator.hpp"
#include "springs/simulate.hpp"
#include "springs/stability.hpp"

namespace sp = creaturelab::springs;

namespace {

constexpr int kColumns = 70, kRows = 100, kSprings = 10000;
constexpr double kSpacingM = 1e-3;

// A sheet of 100 threads of 70 particles (6,900 springs along x, ends pinned), tied by 3,100
// cross springs along y spread evenly over the 6,930 neighbour pairs. Springs at rest length.
struct Web {
  std::unique_ptr<sp::System<3>> system;
  sp::State<3> state;
};

Web makeWeb() {
  sp::Network<3> n;
  sp::State<3> s = sp::zeroState<3>(kColumns * kRows);
  auto id = [](int i, int j) { return j * kColumns + i; };
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      n.addParticle(10e-9, i == 0 || i == kColumns - 1);
      s.x_m.col(id(i, j)) << kSpacingM * i, kSpacingM * j, 0;
    }
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i + 1 < kColumns; ++i) n.addSpring(id(i, j), id(i + 1, j), kSpacingM, 0.01);
  const long pairs = static_cast<long>(kColumns) * (kRows - 1);
  const long cross = kSprings - n.springCount();
  for (long q = 0; q < pairs; ++q) {
    if ((q + 1) * cross / pairs == q * cross / pairs) continue;
    const int i = static_cast<int>(q % kColumns), j = static_cast<int>(q / kColumns);
    n.addSpring(id(i, j), id(i, j + 1), kSpacingM, 0.01);
  }
  n.gravity_m_per_s2 << 0, 0, -9.81;
  n.drag_ns_per_m = 1e-8;
  return {std::make_unique<sp::System<3>>(n), s};
}

const Web& web() {
  static const Web w = makeWeb();
  return w;
}

double symplecticAutoStepS() {
  const auto& w = web();
  const double omega = sp::estimateOmegaMaxRadPerS(w.system->network(), w.state);
  const auto zeta = sp::estimateDampingRatio(w.system->network(), omega);
  const double dt = sp::autoStepS(sp::IntegratorKind::SymplecticEuler, omega, zeta.high);
  return 0.02 / std::ceil(0.02 / dt);
}

void setCounters(benchmark::State& st, int particles) {
  st.counters["particle_steps_per_s"] = benchmark::Counter(particles, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Forces(benchmark::State& st) {
  const auto& w = web();
  sp::Points<3> f;
  for (auto _ : st) {
    w.system->forces(w.state, 0.0, f);
    benchmark::DoNotOptimize(f.data());
  }
  setCounters(st, w.system->particleCount());
  st.counters["springs"] = w.system->network().springCount();
}
BENCHMARK(BM_Forces);

void BM_Step(benchmark::State& st) {
  const auto kind = static_cast<sp::IntegratorKind>(st.range(0));
  const auto& w = web();
  sp::State<3> s = w.state;
  auto integrator = sp::makeIntegrator<3>(kind);
  const double dt = symplecticAutoStepS();
  long i = 0;
  for (auto _ : st) {
    // Back to the initial state every 64 steps: explicit Euler is unstable at this step and would
    // otherwise reach inf/NaN, which runs at a different speed (the copy costs ~1 %).
    if ((i & 63) == 63) s = w.state;
    integrator->step(*w.system, s, {static_cast<double>(i++) * dt, dt});
    benchmark::DoNotOptimize(s.x_m.data());
  }
  st.SetLabel(std::string(sp::integratorName(kind)));
  setCounters(st, w.system->particleCount());
}
BENCHMARK(BM_Step)
    ->Arg(static_cast<int>(sp::IntegratorKind::ExplicitEuler))
    ->Arg(static_cast<int>(sp::IntegratorKind::SymplecticEuler))
    ->Arg(static_cast<int>(sp::IntegratorKind::RK4))
    ->Arg(static_cast<int>(sp::IntegratorKind::ImplicitEuler));

void BM_Simulate10sSymplecticAuto(benchmark::State& st) {
  const auto& w = web();
  sp::SimulationSummary summary;
  for (auto _ : st) {
    sp::State<3> s = w.state;
    sp::SimulationOptions opt;
    opt.integrator = sp::IntegratorKind::SymplecticEuler;
    opt.end_time_s = 10;
    summary = sp::simulate(*w.system, s, opt);
    benchmark::DoNotOptimize(s.x_m.data());
  }
  st.counters["steps"] = static_cast<double>(summary.steps);
  st.counters["dt_us"] = summary.dt_used_s * 1e6;
  st.counters["omega_max"] = summary.omega_max_rad_per_s;
  st.counters["particle_steps_per_s"] =
      benchmark::Counter(static_cast<double>(summary.steps) * w.system->particleCount(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Simulate10sSymplecticAuto)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
