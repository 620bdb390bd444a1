// Lid-driven cavity at Re = 100 against Ghia, Ghia & Shin 1982 (J. Comput. Phys. 48, Table I–II):
// a check of the no-slip and moving-wall conditions and of the implicit viscosity (here α =
// ν dt / dx² ≈ 0.03, so the CG path runs), at a steady state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "fluid/fluid_solver2.hpp"

namespace creaturelab::fluid {
namespace {

struct CavityProfile {
  double min_u_centre = 0.0;  // min of u on the vertical centreline
  double max_v_centre = 0.0;  // max and min of v on the horizontal centreline
  double min_v_centre = 0.0;
  double steady_change = 0.0;  // relative velocity change over the last second
};

CavityProfile run_cavity(AdvectionScheme scheme, int cells) {
  FluidParams params;
  params.domain_width_m = params.domain_height_m = 1.0;
  params.cells_x = params.cells_y = cells;
  params.density_kg_per_m3 = 1.0;
  params.kinematic_viscosity_m2_per_s = 0.01;  // Re = U L / ν = 100
  params.advection = scheme;
  params.walls.left.type = params.walls.right.type = params.walls.bottom.type = WallType::no_slip;
  params.walls.top.type = WallType::moving;
  params.walls.top.tangential_velocity_m_per_s = 1.0;
  params.cfl_safety_factor = 0.5;
  params.max_step_s = 0.02;
  FluidSolver2 solver(params);
  MacGrid2 previous;
  bool snapshot_taken = false;
  while (solver.time_s() < 20.0) {
    if (solver.time_s() >= 19.0 && !snapshot_taken) {
      previous = solver.grid();  // one second before the end
      snapshot_taken = true;
    }
    const FluidStepReport report = solver.step();
    EXPECT_TRUE(report.viscosity.converged);
  }
  const MacGrid2& g = solver.grid();
  CavityProfile profile;
  // u on the vertical centreline x = 0.5 (u faces i = n/2), v on the horizontal one (v faces j = n/2).
  for (int j = 0; j < cells; ++j) profile.min_u_centre = std::min(profile.min_u_centre, g.u_m_per_s(cells / 2, j));
  for (int i = 0; i < cells; ++i) {
    profile.max_v_centre = std::max(profile.max_v_centre, g.v_m_per_s(i, cells / 2));
    profile.min_v_centre = std::min(profile.min_v_centre, g.v_m_per_s(i, cells / 2));
  }
  double change = 0.0;
  for (std::size_t k = 0; k < g.u_m_per_s.size(); ++k) {
    change = std::max(change, std::abs(g.u_m_per_s.data()[k] - previous.u_m_per_s.data()[k]));
  }
  profile.steady_change = change;
  return profile;
}

TEST(LidDrivenCavity, MatchesGhiaAtRe100) {
  // Ghia et al. 1982, Re = 100: u_min = −0.21090 (y = 0.4531), v_max = 0.17527 (x = 0.2344),
  // v_min = −0.24533 (x = 0.8047).
  const double u_min_ref = -0.21090, v_max_ref = 0.17527, v_min_ref = -0.24533;
  for (AdvectionScheme scheme : {AdvectionScheme::semi_lagrangian, AdvectionScheme::maccormack}) {
    const CavityProfile p = run_cavity(scheme, 64);
    std::printf(
        "  cavity Re=100, 64x64, %-15s u_min %.4f (Ghia %.4f)  v_max %.4f (%.4f)  v_min %.4f (%.4f)  "
        "change over last s %.1e\n",
        std::string(to_string(scheme)).c_str(), p.min_u_centre, u_min_ref, p.max_v_centre, v_max_ref, p.min_v_centre,
        v_min_ref, p.steady_change);
    const double tolerance = scheme == AdvectionScheme::maccormack ? 0.05 : 0.10;
    EXPECT_NEAR(p.min_u_centre, u_min_ref, tolerance * std::abs(u_min_ref)) << to_string(scheme);
    EXPECT_NEAR(p.max_v_centre, v_max_ref, tolerance * v_max_ref) << to_string(scheme);
    EXPECT_NEAR(p.min_v_centre, v_min_ref, tolerance * std::abs(v_min_ref)) << to_string(scheme);
    EXPECT_LT(p.steady_change, 1e-3);
  }
}

}  // namespace
}  // namespace creaturelab::fluid
