// What a run of the fluid alone records (fluid/fluid_recorder2.hpp): frames exactly at the output
// times, the series and fields of each, the tracers, and the Taylor-Green measures.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "fluid/fluid_recorder2.hpp"
#include "fluid/initial_conditions2.hpp"

namespace creaturelab::fluid {
namespace {

FluidParams smallBox() {
  FluidParams p;
  p.cells_x = p.cells_y = 16;
  p.kinematic_viscosity_m2_per_s = 1e-4;
  return p;
}

TEST(FluidRecorder, FramesLandExactlyOnTheOutputTimesWithAdaptiveSteps) {
  FluidSolver2 solver(smallBox());
  setTaylorGreen(solver.grid(), {0.05});
  solver.makeDivergenceFree();
  solver.tracers_m() = {{0.1, 0.1}, {0.3, 0.2}};
  FluidRecorder2 recorder(solver);
  advanceRecorded(solver, 0.25, 0.1, recorder);
  // 0, 0.1, 0.2 and the end 0.25: the last interval cut short by the end.
  ASSERT_EQ(recorder.frameTimes().size(), 4u);
  EXPECT_EQ(recorder.frameTimes()[0], 0.0);
  EXPECT_NEAR(recorder.frameTimes()[1], 0.1, 1e-12);
  EXPECT_NEAR(recorder.frameTimes()[2], 0.2, 1e-12);
  EXPECT_NEAR(recorder.frameTimes()[3], 0.25, 1e-12);
  EXPECT_GT(solver.stepsDone(), 3);  // the CFL limit cuts the intervals into several steps
  for (const auto& s : recorder.series()) EXPECT_EQ(s.values.size(), 4u) << s.name;
  for (const auto& f : recorder.fields()) EXPECT_EQ(f.values.size(), 4u * 16 * 16) << f.name;
  EXPECT_EQ(recorder.tracers(), 2);
  EXPECT_EQ(recorder.tracerData().size(), 4u * 2 * 2);
  EXPECT_EQ(recorder.series()[3].values[0], 0.0);  // no step before the first frame: CFL 0
  EXPECT_GT(recorder.series()[3].values[1], 0.0);
}

TEST(FluidRecorder, TaylorGreenMeasuresFollowTheExactDecay) {
  FluidSolver2 solver(smallBox());
  setTaylorGreen(solver.grid(), {0.05});
  solver.makeDivergenceFree();
  FluidRecorder2 recorder(solver);
  advanceRecorded(solver, 0.2, 0.1, recorder);
  std::optional<double> linf, nu_eff, ratio, rest_linf;
  for (const auto& m : recorder.measure(solver, TaylorGreenVortex{0.05})) {
    if (m.name == "velocity_error_linf_m_per_s") linf = m.value;
    if (m.name == "effective_viscosity_m2_per_s") nu_eff = m.value;
    if (m.name == "kinetic_energy_ratio") ratio = m.value;
  }
  ASSERT_TRUE(linf && nu_eff && ratio);
  EXPECT_LT(*linf, 0.05 * 0.05);     // within 5% of the amplitude on 16 cells
  EXPECT_GT(*nu_eff, 1e-4);         // the physical viscosity plus the scheme's own, never less
  EXPECT_LT(*ratio, 1.0);
  for (const auto& m : recorder.measure(solver, std::nullopt))
    if (m.name == "velocity_error_linf_m_per_s") rest_linf = m.value;
  ASSERT_TRUE(rest_linf);
  EXPECT_TRUE(std::isnan(*rest_linf));  // no exact solution to compare with
}

}  // namespace
}  // namespace creaturelab::fluid
