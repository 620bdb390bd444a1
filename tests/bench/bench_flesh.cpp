// Speed of one flesh step (flesh/flesh.hpp) followed by the skeleton's MuJoCo step, on the swimmer
// and the flyer of experiments/control/models, their flesh refined to a maximum edge (arguments: the
// edge in millimetres; 0 = the 16-slice tessellation), with the skeleton in the solve (implicit) and
// without. Counters: vertices, CG iterations per step. A disturbed flesh, so CG has
// work; the figures compare only against a build run beside them.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "flesh/flesh.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::flesh {
namespace {

void stepFlesh(benchmark::State& state, const char* creature, bool implicit) {
  const auto model =
      rigid::RigidModel::load(std::string(CREATURELAB_SOURCE_DIR) + "/experiments/control/models/" + creature + ".xml");
  FleshParams p;
  p.max_edge_m = 1e-3 * double(state.range(0));
  p.implicit_skeleton = implicit;
  Flesh flesh(model, p);
  rigid::RigidData skeleton(model);
  flesh.placeOnSkeleton(skeleton);
  Eigen::Matrix3Xd v = flesh.velocities_m_per_s();
  for (int i = 0; i < flesh.vertices(); ++i)
    for (int d = 0; d < 3; ++d) v(d, i) += 0.1 * std::cos(0.7 * i + 1.7 * d);
  flesh.setState(flesh.positions_m(), v);
  const double h = model.timestep_s();
  double iterations = 0;
  for (auto _ : state) {
    flesh.step(skeleton, h);
    skeleton.step();
    std::fill(skeleton.appliedForces(), skeleton.appliedForces() + model.dofs(), 0.0);
    iterations += flesh.lastStep().cg_iterations;
  }
  state.counters["vertices"] = flesh.vertices();
  state.counters["cg_iterations"] = iterations / double(state.iterations());
}

BENCHMARK_CAPTURE(stepFlesh, swimmer_implicit, "swimmer", true)->Arg(0)->Arg(40)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stepFlesh, swimmer_explicit, "swimmer", false)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stepFlesh, flyer_implicit, "flyer", true)->Arg(0)->Arg(40)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace creaturelab::flesh
