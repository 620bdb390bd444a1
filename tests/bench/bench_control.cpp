// Speed of the creature controller (Lentine et al. 2010 Fig. 14: 0.03 s per frame for
// the simple-force block, 0.26-0.81 s for the humans, unparallelised, 2010 hardware; Fig. 10:
// serial time per frame grows linearly with the controlled joints, parallel stays flat).
// Goals: the block at >= 1,000 frames per second on one core, the human with three controlled
// joints at >= 30. One iteration is one frame: the
// central differences (two evaluations of one frame each per controlled DOF), the step and the
// recorded measures. Reported as frames per CPU second of the process ("frames_per_cpu_s", all
// threads counted) and per elapsed second ("frames_per_s").
#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

#include "control/controller.hpp"
#include "control/simple_wind.hpp"
#include "frame_timing.hpp"

namespace creaturelab::control {
namespace {

void runFrames(benchmark::State& state, const rigid::RigidModel& model, const ControllerParams& p, const Vec3& wind,
               int slices) {
  const SimpleWind force(rigid::geomSurfaces(model, slices), 1.2, constantWind(wind));
  Controller c(model, p, force);
  bench::timeFrames(state, c);
}

// The block of block_effort.toml: one controlled hinge, gravity and a 10 m/s wind, min effort.
void BM_BlockFrame(benchmark::State& state) {
  auto model = rigid::RigidModel::load(std::string(CREATURELAB_SOURCE_DIR) + "/experiments/control/models/block.xml");
  ControllerParams p;
  p.controlled = {"hinge"};
  p.objectives = {Objective::effort};
  p.senses = {Sense::minimize};
  model.setTimestep(p.frame_s);
  runFrames(state, model, p, {10, 0, 0}, 12);
}
BENCHMARK(BM_BlockFrame)->Unit(benchmark::kMicrosecond);

// A planar chain of 5 capsules (experiments/control/models/chain.xml) with the first
// range(0) joints controlled (effort), on range(1) threads: Fig. 10's table.
void BM_ChainFrame(benchmark::State& state) {
  auto model = rigid::RigidModel::load(std::string(CREATURELAB_SOURCE_DIR) + "/experiments/control/models/chain.xml");
  ControllerParams p;
  for (int k = 0; k < state.range(0); ++k) {
    p.controlled.push_back("j" + std::to_string(k));
    p.objectives.push_back(Objective::effort);
    p.senses.push_back(Sense::minimize);
  }
  p.threads = int(state.range(1));
  model.setTimestep(p.frame_s);
  runFrames(state, model, p, {10, 0, 0}, 12);
}
BENCHMARK(BM_ChainFrame)->ArgsProduct({{1, 2, 3, 4}, {1, 2}})->Unit(benchmark::kMicrosecond);

// The human of human_gravity.toml (a): three controlled joints minimising the lower back's effort,
// kinematic legs, contacts, 4 substeps per frame; on range(0) threads. Goal: >= 30 frames per
// second on one core (real time).
void BM_HumanFrame(benchmark::State& state) {
  auto model =
      rigid::RigidModel::load(std::string(CREATURELAB_SOURCE_DIR) + "/experiments/control/models/humanoid_upper.xml");
  ControllerParams p;
  p.controlled = {"lower_back", "right_shoulder", "left_shoulder"};
  p.kinematic = {"right_hip_y", "right_knee", "left_hip_y", "left_knee"};
  p.objectives = {Objective::effort, Objective::effort, Objective::effort};
  p.senses = {Sense::minimize, Sense::minimize, Sense::minimize};
  p.weights = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  p.substeps = 4;
  p.threads = int(state.range(0));
  model.setTimestep(p.frame_s / p.substeps);
  runFrames(state, model, p, {20, 0, 0}, 12);
}
BENCHMARK(BM_HumanFrame)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// The same human with walking legs (kinematic sine patterns) and PD-driven elbows, as
// human_gravity.toml (c): the patterns' cost against BM_HumanFrame.
void BM_HumanWalkingFrame(benchmark::State& state) {
  auto model =
      rigid::RigidModel::load(std::string(CREATURELAB_SOURCE_DIR) + "/experiments/control/models/humanoid_upper.xml");
  ControllerParams p;
  p.controlled = {"lower_back", "right_shoulder", "left_shoulder"};
  p.kinematic = {"right_hip_y", "right_knee", "left_hip_y", "left_knee"};
  auto sine = [](double mean, double amplitude, double phase) {
    Pattern s;
    s.kind = Pattern::Kind::sine;
    s.mean_rad = mean;
    s.amplitude_rad = amplitude;
    s.frequency_hz = 1;
    s.phase_rad = phase;
    return s;
  };
  p.kinematic_patterns = {sine(0, 0.35, 0), sine(0.35, 0.35, 1.57), sine(0, 0.35, 3.14), sine(0.35, 0.35, 4.71)};
  p.pd_driven = {"right_elbow", "left_elbow"};
  p.pd_patterns = {sine(-0.35, 0.35, 1.57), sine(-0.35, 0.35, 4.71)};
  p.objectives = {Objective::effort, Objective::effort, Objective::effort};
  p.senses = {Sense::minimize, Sense::minimize, Sense::minimize};
  p.weights = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  p.substeps = 4;
  model.setTimestep(p.frame_s / p.substeps);
  runFrames(state, model, p, {0, 0, 0}, 12);
}
BENCHMARK(BM_HumanWalkingFrame)->Unit(benchmark::kMillisecond);

// The block on a ball joint (block_ball.toml): three controlled DOFs, six evaluations a frame.
void BM_BallBlockFrame(benchmark::State& state) {
  auto model =
      rigid::RigidModel::load(std::string(CREATURELAB_SOURCE_DIR) + "/experiments/control/models/block_ball.xml");
  ControllerParams p;
  p.controlled = {"ball"};
  p.objectives = {Objective::effort};
  p.senses = {Sense::minimize};
  model.setTimestep(p.frame_s);
  runFrames(state, model, p, {8.66, 5, 0}, 12);
}
BENCHMARK(BM_BallBlockFrame)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace creaturelab::control
