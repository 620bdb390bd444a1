// Speed of one coupled step of MuJoCo bodies in the 3-D fluid (coupling3d/rigid_fluid_coupling3.hpp)
// at 32³ and 64³, 1 and 2 fluid threads: milliseconds of CPU per step ("ms_per_step", all threads),
// elapsed ("ms_per_step_wall"), the projected forcing's CG iterations and the marker count. Scene: the
// flyer's box (0.4 m of water, no-slip walls, an open top, MG-PCG) with a sphere (radius 0.05 m) and a
// plate (0.12 × 0.08 × 0.01 m) moved kinematically on circles, markers half a cell apart. Figures from
// different hosts or hours compare only against a build run beside them. BM_FreeSphereStep3: the projected
// and the coupled forcing on a free sphere at 32³.
#include <benchmark/benchmark.h>
#include <time.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <unistd.h>

#include "coupling3d/rigid_fluid_coupling3.hpp"

namespace creaturelab::coupling3d {
namespace {

double clockSeconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

rigid::RigidModel scene() {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("bench_coupling3d_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(path) << "<mujoco><option timestep=\"0.01\" gravity=\"0 0 0\"/>"
                         "<default><geom contype=\"0\" conaffinity=\"0\"/></default><worldbody>"
                         "<body pos=\"0.14 0.2 0.2\"><freejoint/><geom type=\"sphere\" size=\"0.05\"/></body>"
                         "<body pos=\"0.27 0.2 0.2\"><freejoint/><geom type=\"box\" size=\"0.06 0.04 0.005\"/></body>"
                         "</worldbody></mujoco>";
  rigid::RigidModel model = rigid::RigidModel::load(path.string());
  std::filesystem::remove(path);
  return model;
}

void BM_CoupledStep3(benchmark::State& state) {
  const int cells = static_cast<int>(state.range(0));
  const rigid::RigidModel model = scene();
  rigid::RigidData data(model);
  data.kinematics();
  fluid3d::FluidParams3 f;  // 0.4 m box of water
  f.cells_x = f.cells_y = f.cells_z = cells;
  f.boundaries = fluid3d::Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip);
  f.boundaries.axis[2].high = fluid3d::BoundaryType3::open;
  f.threads = static_cast<int>(state.range(1));
  f.pressure_tolerance = 1e-8;
  RigidFluidCoupling3 c(data, f, {});
  const double dt = 0.01, speed = 0.05, radius = 0.02;  // circles of 2 cm at 5 cm/s
  const double base[2][3] = {{0.14, 0.2, 0.2}, {0.27, 0.2, 0.2}};
  long step = 0;
  auto advance = [&]() {
    ++step;
    const double phase = speed / radius * dt * static_cast<double>(step);
    c.advanceFluid(dt);
    for (int b = 0; b < 2; ++b) {
      data.qpos()[7 * b + 0] = base[b][0] + radius * std::cos(phase) - radius;
      data.qpos()[7 * b + 2] = base[b][2] + radius * std::sin(phase);
    }
    data.kinematics();
    c.forceFluid(data, dt);
  };
  for (int s = 0; s < 3; ++s) advance();
  double cpu = 0.0, wall = 0.0;
  long iterations = 0;
  for (auto _ : state) {
    const double cpu0 = clockSeconds(CLOCK_PROCESS_CPUTIME_ID), wall0 = clockSeconds(CLOCK_MONOTONIC);
    advance();
    cpu += clockSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
    wall += clockSeconds(CLOCK_MONOTONIC) - wall0;
    iterations += c.forcingIterations();
    state.SetIterationTime(clockSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["ms_per_step"] = 1e3 * cpu / n;
  state.counters["ms_per_step_wall"] = 1e3 * wall / n;
  state.counters["forcing_iterations"] = static_cast<double>(iterations) / n;
  state.counters["markers"] = static_cast<double>(c.markers().size());
}

BENCHMARK(BM_CoupledStep3)->ArgsProduct({{32, 64}, {1, 2}})->UseManualTime()->Unit(benchmark::kMillisecond);

// The forcings side by side on a free body: the same box at 32³ with a free sphere (radius 0.05 m, ten times
// the water's density: the projected forcing is stable there) thrown at 0.1 m/s, MuJoCo stepping it; range(0)
// 0 projected (the reaction one step late), 1 coupled (Lentine et al. 2010 Eq. 9: the sphere's velocity in
// the forcing's solve). One fluid thread.
void BM_FreeSphereStep3(benchmark::State& state) {
  const bool coupled = state.range(0) == 1;
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("bench_coupling3d_free_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(path) << "<mujoco><option timestep=\"0.01\" gravity=\"0 0 0\"/>"
                         "<default><geom contype=\"0\" conaffinity=\"0\"/></default><worldbody>"
                         "<body pos=\"0.12 0.2 0.2\"><freejoint/><geom type=\"sphere\" size=\"0.05\" density=\"10000\"/></body>"
                         "</worldbody></mujoco>";
  const rigid::RigidModel model = rigid::RigidModel::load(path.string());
  std::filesystem::remove(path);
  rigid::RigidData data(model);
  data.qvel()[0] = 0.1;
  data.kinematics();
  fluid3d::FluidParams3 f;  // 0.4 m box of water
  f.cells_x = f.cells_y = f.cells_z = 32;
  f.boundaries = fluid3d::Boundaries3::allWalls(fluid3d::BoundaryType3::no_slip);
  f.boundaries.axis[2].high = fluid3d::BoundaryType3::open;
  f.pressure_tolerance = 1e-8;
  RigidFluidParams3 p;
  p.forcing = coupled ? Forcing3::coupled : Forcing3::projected;
  RigidFluidCoupling3 c(data, f, p);
  const double dt = 0.01;
  auto advance = [&]() {
    c.advanceFluid(dt);
    for (int d = 0; d < model.dofs(); ++d) data.appliedForces()[d] = 0;
    c.applyReaction(data);
    data.step();
    data.kinematics();
    c.forceFluid(data, dt);
  };
  for (int s = 0; s < 3; ++s) advance();
  double cpu = 0.0;
  long iterations = 0;
  for (auto _ : state) {
    const double cpu0 = clockSeconds(CLOCK_PROCESS_CPUTIME_ID);
    advance();
    cpu += clockSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
    iterations += c.forcingIterations();
    state.SetIterationTime(clockSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["ms_per_step"] = 1e3 * cpu / n;
  state.counters["forcing_iterations"] = static_cast<double>(iterations) / n;
  state.counters["markers"] = static_cast<double>(c.markers().size());
}

BENCHMARK(BM_FreeSphereStep3)->Arg(0)->Arg(1)->Iterations(20)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace creaturelab::coupling3d
