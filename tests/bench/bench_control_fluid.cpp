// Speed of the controller in the coupled fluid (Lentine et al. 2010 Fig. 14: 14-15 s per
// frame for the Navier-Stokes block, Fig. 10: 14/29/43/58 s serial and 14-15 s parallel on four
// processors for 1-4 controlled joints). Goals: the block in a 128^2 fluid at >= 10 frames per
// second with one controlled joint on one core; per-frame time flat (within 20%) from 1 to 2
// controlled joints on 2 cores. One iteration is one frame: the central differences (two
// evaluations of one frame of coupled steps per controlled DOF, each on its own copy of the
// fluid), the frame itself and its measures; the flow is developed for 0.5 s first.
// Reported as frames per CPU second of the process and per elapsed second. BM_FlyerFrame: the
// driven flyer (flyer_quick.toml's setting), per-frame time reported, no goal set.
#include <benchmark/benchmark.h>

#include <string>

#include "control/fluid_controller.hpp"
#include "frame_timing.hpp"

namespace creaturelab::control {
namespace {

fluid::FluidParams box128() {
  fluid::FluidParams f;
  f.domain_width_m = f.domain_height_m = 4.0;
  f.cells_x = f.cells_y = 128;
  f.kinematic_viscosity_m2_per_s = 0;
  f.walls.left.type = f.walls.right.type = fluid::WallType::open;
  return f;
}

coupling::ForcingPreconditioner preconditioner(benchmark::State& state, int arg) {
  const bool gram = state.range(arg) != 0;
  state.counters["gram_preconditioner"] = gram;
  return gram ? coupling::ForcingPreconditioner::gram : coupling::ForcingPreconditioner::mass;
}

coupling::RigidFluidParams stream(coupling::ForcingPreconditioner pc) {
  coupling::RigidFluidParams c;
  c.forcing_preconditioner = pc;
  c.origin_x_m = -1.2;
  c.origin_z_m = -2.0;
  c.inflow.stream_m_per_s = 1.0;
  c.inflow.stream_columns = 3;
  return c;
}

rigid::RigidModel loadModel(const std::string& file, const ControllerParams& p) {
  auto model = rigid::RigidModel::load(std::string(CREATURELAB_SOURCE_DIR) + file);
  model.setGravity({0, 0, 0});
  model.setTimestep(p.frame_s / p.substeps);
  return model;
}

// bench::timeFrames, and the forcing's most CG iterations.
void timeFrames(benchmark::State& state, FluidController& c) {
  bench::timeFrames(state, c);
  state.counters["max_cg_iterations"] = c.maxForcingIterations();
}

void runFrames(benchmark::State& state, const std::string& file, const ControllerParams& p, int settle,
               const std::vector<std::pair<std::string, double>>& initial, coupling::ForcingPreconditioner pc,
               int fluid_threads = 1) {
  const auto model = loadModel(file, p);
  FluidControlParams f;
  f.settle_steps = settle;
  f.average_steps = settle > 0 ? settle / 3 : 1;
  fluid::FluidParams box = box128();
  box.threads = fluid_threads;
  FluidController c(model, p, f, initial, box, stream(pc));
  c.hold(30);  // the flow develops
  timeFrames(state, c);
}

// block_flow.toml's block, minimising drag along the stream; range(0) settle steps (0: none, the
// paper's complex examples; 30: block_flow's validation mode); range(1) the forcing's preconditioner
// (0 mass, 1 gram).
void BM_BlockFluidFrame(benchmark::State& state) {
  ControllerParams p;
  p.controlled = {"hinge"};
  p.objectives = {Objective::drag_along};
  p.senses = {Sense::minimize};
  p.delta_rad = 0.03;
  runFrames(state, "/experiments/control/models/block.xml", p, int(state.range(0)), {{"hinge", -0.5}},
            preconditioner(state, 1));
}
BENCHMARK(BM_BlockFluidFrame)
    ->ArgNames({"settle", "gram"})
    ->ArgsProduct({{0, 30}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);

// The chain of parallel_dofs.toml (five capsules, 2 m) in the stream with the first range(0)
// joints controlled, on range(1) threads for the evaluations and range(2) inside the frame's own
// fluid steps (fluid_threads): Fig. 10 with the fluid.
void BM_ChainFluidFrame(benchmark::State& state) {
  ControllerParams p;
  for (int k = 0; k < state.range(0); ++k) {
    p.controlled.push_back("j" + std::to_string(k));
    p.objectives.push_back(Objective::drag_along);
    p.senses.push_back(Sense::minimize);
  }
  // The rest held: free, the light capsules are unstable in the staggered coupling (added mass).
  for (int k = int(state.range(0)); k < 5; ++k) p.kinematic.push_back("j" + std::to_string(k));
  p.threads = int(state.range(1));
  p.delta_rad = 0.01;  // the 2 m chain's tip within one cell per step (parallel_dofs_fluid.toml)
  p.strength_rad_per_s = 0.5;
  p.substeps = 2;  // four joints stepping together within one cell per step
  runFrames(state, "/experiments/control/models/chain.xml", p, 0, {{"j0", -0.3}},
            coupling::ForcingPreconditioner::mass, int(state.range(2)));
}
BENCHMARK(BM_ChainFluidFrame)
    ->Args({1, 1, 1})->Args({1, 1, 2})->Args({1, 2, 2})->Args({2, 1, 1})->Args({2, 2, 1})->Args({2, 2, 2})->Args({3, 1, 1})
    ->Args({4, 1, 1})->Args({4, 2, 1})->Args({4, 2, 2})
    ->Unit(benchmark::kMillisecond)->Iterations(10);

// The driven flyer (§7.1, Figs. 11-13; models/flyer.xml) in flyer_quick.toml's setting: 128^2 air
// (nu 0.005 m^2/s) in a 4 m box with the inflow floor (0.5 m/s) and an open top, inner wing joints
// PD-driven (30 deg, 0.5 Hz), the two outer joints controlled (drag, sense following the stroke) in
// validation mode (8 settle steps, force over 4) and 4 coupled steps a frame. The paper: 3.2 s per
// frame for the flyer without flesh (§7, its timing table). range(0) evaluation threads, range(1)
// cells per side, range(2) the forcing's preconditioner (0 mass, 1 gram).
void BM_FlyerFrame(benchmark::State& state) {
  ControllerParams p;
  p.controlled = {"outer_r", "outer_l"};
  p.objectives = {Objective::drag, Objective::drag};
  p.senses = {Sense::maximize, Sense::maximize};
  Pattern flap;
  flap.kind = Pattern::Kind::sine;
  flap.amplitude_rad = 30 * 3.141592653589793 / 180;
  flap.frequency_hz = 0.5;
  p.pd_driven = {"inner_r", "inner_l"};
  p.pd_patterns = {flap, flap};
  p.pd_kp_n_m_per_rad = 800;
  p.pd_kd_n_m_s_per_rad = 40;
  p.substeps = 4;
  p.strength_rad_per_s = 2.0;
  p.delta_rad = 0.02;
  p.threads = int(state.range(0));
  const auto model = loadModel("/experiments/control/models/flyer.xml", p);
  FluidControlParams f;
  f.settle_steps = 8;
  f.average_steps = 4;
  f.limit_rad = 3.141592653589793 / 2;
  f.stroke = {{"inner_r", 1.0}, {"inner_l", 1.0}};
  fluid::FluidParams box = box128();
  box.cells_x = box.cells_y = int(state.range(1));
  box.density_kg_per_m3 = 1.2;
  box.kinematic_viscosity_m2_per_s = 0.005;
  box.walls.left.type = box.walls.right.type = fluid::WallType::free_slip;
  box.walls.bottom.type = fluid::WallType::inflow;
  box.walls.bottom.inflow_m_per_s = 0.5;
  box.walls.top.type = fluid::WallType::open;
  coupling::RigidFluidParams source;
  source.origin_x_m = source.origin_z_m = -2.0;
  source.inflow.stream_m_per_s = 0.0;
  source.inflow.source_m_per_s = 0.5;
  source.inflow.source_rows = 0;
  source.forcing_preconditioner = preconditioner(state, 2);
  FluidController c(model, p, f, {}, box, source);
  c.hold(30);
  timeFrames(state, c);
}
BENCHMARK(BM_FlyerFrame)
    ->ArgNames({"threads", "cells", "gram"})
    ->ArgsProduct({{1, 2}, {128}, {0, 1}})
    ->Args({1, 256, 0})
    ->Args({1, 256, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);

// The swimmer of experiments/control/swimmer.toml (Lentine et al. 2010 §7.2, Fig. 7;
// goal: >= 1 frame per second on one core, 128^2): five controlled legs, the mouth's phases, the
// free root stabilised by its armature, range(0)^2 cells in 3 m (128; 192: swimmer.toml's grid),
// closed walls but the open top. One iteration is one frame in phase 1 (draw in, minimise the
// downward force), the fluid at rest before. range(1): the forcing's preconditioner (0 mass, 1 gram).
void BM_SwimmerFrame(benchmark::State& state) {
  ControllerParams p;
  p.controlled = {"leg_l2", "leg_l1", "leg_r1", "leg_r2", "leg_top"};
  p.objectives.assign(5, Objective::drag_along);
  p.senses.assign(5, Sense::minimize);
  p.drag_direction = {0, 0, -1};
  p.delta_rad = 0.02;
  p.strength_rad_per_s = 0.5;  // the legs stay within a half-turn over the benchmark's frames
  p.threads = 1;
  const auto model = loadModel("/experiments/control/models/swimmer.xml", p);
  FluidControlParams f;
  f.armature_added_mass = true;
  fluid::FluidParams fp;
  fp.domain_width_m = fp.domain_height_m = 3.0;
  fp.cells_x = fp.cells_y = int(state.range(0));
  fp.kinematic_viscosity_m2_per_s = 0;
  fp.walls.top.type = fluid::WallType::open;
  coupling::RigidFluidParams cp;
  cp.origin_x_m = -1.5;
  cp.origin_z_m = -1.0;
  cp.max_forcing_iterations = 100;
  cp.forcing_preconditioner = preconditioner(state, 1);
  cp.mouth.body = "body";
  cp.mouth.centre_z_m = -0.21;
  cp.mouth.width_m = 0.14;
  cp.mouth.schedule.fractions = {1.0};
  cp.mouth.flux_m_per_s = {-0.5};
  FluidController c(model, p, f, {}, fp, cp);
  timeFrames(state, c);
}
BENCHMARK(BM_SwimmerFrame)
    ->ArgNames({"cells", "gram"})
    ->ArgsProduct({{128, 192}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);

}  // namespace
}  // namespace creaturelab::control
