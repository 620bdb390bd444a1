// The default orb web (A. Mehla, Modeling and Animation of Orb Webs, MSc thesis, University of Saskatchewan
// 2005, §5.2; ~6,100 particles, ~9,500 springs).
// Goals (Release, one core):
//   BM_BuildDefaultWeb              build the web                                  <= 50 ms
//   BM_Settle10sRK4Auto             10 simulated seconds, RK4 at its auto substep   <= 3 s
//                                   (the web's: web::kAutoStepSafety = 1, the full stability limit
//                                   of an upper bound on omega_max, so still a stable step)
//   BM_StaticEquilibrium            Newton static equilibrium from the laid web     <= 0.2 s
// BM_Settle10sRK4HalfLimit runs RK4 at half that step (the engine's default auto_safety, 0.5) for
// comparison. The web is planar, so simulate() integrates it in 2D (the same result, bit for bit).
// BM_WebAccelerations and BM_WebRK4Step time one force evaluation and one RK4 step in 3D.
#include <benchmark/benchmark.h>

#include "springs/equilibrium.hpp"
#include "springs/simulate.hpp"
#include "web/build.hpp"

namespace sp = creaturelab::springs;
namespace web = creaturelab::web;

namespace {

const web::WebModel& defaultWeb() {
  static const web::WebModel m = web::build(web::WebParams{});
  return m;
}

void sizeCounters(benchmark::State& st, const web::WebModel& m) {
  st.counters["particles"] = m.counts.particles;
  st.counters["springs"] = m.counts.springs;
}

void BM_BuildDefaultWeb(benchmark::State& st) {
  const web::WebParams params;
  web::WebCounts counts;
  for (auto _ : st) {
    auto m = web::build(params);
    counts = m.counts;
    benchmark::DoNotOptimize(m.state.x_m.data());
  }
  st.counters["particles"] = counts.particles;
  st.counters["springs"] = counts.springs;
}
BENCHMARK(BM_BuildDefaultWeb)->Unit(benchmark::kMillisecond);

void settle(benchmark::State& st, double auto_safety) {
  const auto& m = defaultWeb();
  sp::System<3> system(m.network);
  system.setConstantForce(m.external_force_n);
  sp::SimulationSummary summary;
  for (auto _ : st) {
    sp::State<3> s = m.state;
    sp::SimulationOptions opt;  // RK4, 0.02 s frames, dt = 0 (auto)
    opt.end_time_s = 10;
    opt.auto_safety = auto_safety;
    summary = sp::simulate(system, s, opt);
    benchmark::DoNotOptimize(s.x_m.data());
  }
  sizeCounters(st, m);
  st.counters["steps"] = static_cast<double>(summary.steps);
  st.counters["dt_us"] = summary.dt_used_s * 1e6;
  st.counters["omega_max"] = summary.omega_max_rad_per_s;
  st.counters["settling_s"] = summary.settling_time_s.value_or(-1);
}

void BM_Settle10sRK4Auto(benchmark::State& st) { settle(st, web::kAutoStepSafety); }
BENCHMARK(BM_Settle10sRK4Auto)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_Settle10sRK4HalfLimit(benchmark::State& st) { settle(st, 0.5); }
BENCHMARK(BM_Settle10sRK4HalfLimit)->Iterations(1)->Unit(benchmark::kMillisecond);

// One force evaluation (System::accelerations: springs, gravity, drag, the constant frame force) at the
// laid state; RK4 makes four per step.
void BM_WebAccelerations(benchmark::State& st) {
  const auto& m = defaultWeb();
  sp::System<3> system(m.network);
  system.setConstantForce(m.external_force_n);
  sp::Points<3> acc;
  for (auto _ : st) {
    system.accelerations(m.state, 0.0, acc);
    benchmark::DoNotOptimize(acc.data());
  }
  sizeCounters(st, m);
}
BENCHMARK(BM_WebAccelerations)->Unit(benchmark::kMicrosecond);

// One RK4 step of 0.4 ms from the laid web.
void BM_WebRK4Step(benchmark::State& st) {
  const auto& m = defaultWeb();
  sp::System<3> system(m.network);
  system.setConstantForce(m.external_force_n);
  auto rk4 = sp::makeIntegrator<3>(sp::IntegratorKind::RK4);
  sp::State<3> s = m.state;
  for (auto _ : st) {
    rk4->step(system, s, sp::StepContext{0.0, 4e-4});
    benchmark::DoNotOptimize(s.x_m.data());
  }
  sizeCounters(st, m);
}
BENCHMARK(BM_WebRK4Step)->Unit(benchmark::kMicrosecond);

void BM_StaticEquilibrium(benchmark::State& st) {
  const auto& m = defaultWeb();
  sp::System<3> system(m.network);
  system.setConstantForce(m.external_force_n);
  sp::EquilibriumResult r;
  for (auto _ : st) {
    sp::State<3> s = m.state;
    r = sp::solveStaticEquilibrium(system, s);
    benchmark::DoNotOptimize(s.x_m.data());
  }
  sizeCounters(st, m);
  st.counters["iterations"] = r.iterations;
  st.counters["converged"] = r.converged;
}
BENCHMARK(BM_StaticEquilibrium)->Unit(benchmark::kMillisecond);

}  // namespace
