// What the membrane test measures (ib/membrane_run.hpp) against closed forms: the energy excess of a
// regular polygon and of a slightly elliptic ring, Laplace's law on a prescribed pressure jump, and a
// ring that does not move losing no area.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "ib/membrane_run.hpp"

namespace ib = creaturelab::ib;
namespace fluid = creaturelab::fluid;

namespace {

std::vector<fluid::Vec2> ringOf(double a_m, double b_m, int n) {
  ib::MembraneParams p;
  p.semi_axis_x_m = a_m;
  p.semi_axis_y_m = b_m;
  p.markers = n;
  return ib::ellipseMarkers(p);
}

}  // namespace

// A regular N-gon has the least energy of its area: excess 0; an ellipse of aspect ratio 1 + 2δ with
// equally spaced markers about 3δ²/2 (aspect 1.05: about 9.4e-4).
TEST(MembraneRun, EnergyExcessOfACircleAndOfAnEllipse) {
  const ib::MembraneBody body(128, 2000.0);
  const auto circle = ringOf(0.2, 0.2, 128);
  EXPECT_NEAR(ib::energyExcess(body, circle, ib::polygonShape(circle).area_m2), 0.0, 1e-9);
  const double b = 0.2, a = 1.05 * b;
  const auto ellipse = ringOf(a, b, 128);
  EXPECT_NEAR(ib::energyExcess(body, ellipse, ib::polygonShape(ellipse).area_m2), 1.5 * 0.025 * 0.025, 1e-4);
}

// Pressure T/R inside the circle and 0 outside: the ratio is 1, whatever the band between holds.
TEST(MembraneRun, LaplaceRatioOfAPrescribedJump) {
  const auto ring = ringOf(0.2, 0.2, 256);
  const ib::PolygonShape shape = ib::polygonShape(ring);
  const double radius = std::sqrt(shape.area_m2 / M_PI), tension = 3.0;
  fluid::MacGrid2 g(100, 100, 0.01);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const fluid::Vec2 c = g.cellCentre_m(i, j);
      const double d = std::hypot(c.x - shape.centroid_m.x, c.y - shape.centroid_m.y);
      g.pressure_pa(i, j) = d < radius ? tension / radius : (d < 1.5 * radius ? 123.0 : 0.0);
    }
  EXPECT_NEAR(ib::laplacePressureRatio(g, shape, tension), 1.0, 1e-12);
}

// A ring held still over two steps of reports: no area lost, the step maxima as reported, the
// series one value per frame.
TEST(MembraneRun, ARingHeldStillLosesNoArea) {
  const ib::MembraneBody body(64, 2000.0);
  const auto ring = ringOf(0.25, 0.15, 64);
  fluid::FluidParams fp;
  fluid::FluidSolver2 fluid(fp);
  ib::MembraneRunRecorder rec(body, ring, 2);
  rec.frame(0.0, ring, fluid);
  ib::CouplingStepReport report;
  report.fluid.cfl_number = 0.3;
  report.max_marker_speed_m_per_s = 0.1;
  rec.step(1, report, ring, 0.01);
  report.fluid.cfl_number = 0.2;
  rec.step(2, report, ring, 0.01);
  rec.frame(0.02, ring, fluid);
  for (const auto& s : rec.series()) EXPECT_EQ(s.values.size(), 2u) << s.name;
  EXPECT_EQ(rec.markerData().size(), 2u * 64 * 2);
  std::map<std::string, double> m;
  for (const auto& v : rec.measure(ring, fluid, 0.01)) m[v.name] = v.value;
  EXPECT_EQ(m.size(), 12u);
  EXPECT_EQ(m.at("area_loss_fraction"), 0.0);
  EXPECT_EQ(m.at("max_cfl"), 0.3);
  EXPECT_EQ(m.at("max_marker_speed_m_per_s"), 0.1);
  EXPECT_EQ(m.at("steps"), 2.0);
}
