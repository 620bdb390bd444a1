// The fluid3d kind end to end on small grids: what it records (series, metrics, the plane of
// fields), the Taylor-Green decay against its exact rate, the updraft's flux, bad input refused in
// words, and a blow-up ending as a RunFailure that keeps the frames written before it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kinds/fluid3d.hpp"

namespace creaturelab::kinds {
namespace {

Params with(const Kind& kind, Params overrides) { return withDefaults(kind, std::move(overrides)); }

Params periodicTaylorGreen(std::int64_t cells) {
  const double side = 2.0 * std::numbers::pi;
  Params p = {{"domain_x_m", side}, {"domain_y_m", side}, {"domain_z_m", side}, {"cells", cells},
              {"kinematic_viscosity_m2_per_s", 0.1}, {"initial", std::string("taylor_green")},
              {"amplitude_m_per_s", 0.001}, {"end_time_s", 1.0}, {"output_interval_s", 0.5},
              {"viscosity_scheme", std::string("crank_nicolson")}, {"pressure_solver", std::string("spectral")},
              {"dt_s", 0.1}};
  for (const char* side_name : {"side_x_low", "side_x_high", "side_y_low", "side_y_high", "side_z_low", "side_z_high"})
    p[side_name] = std::string("periodic");
  return p;
}

// 8³: the decay rate's error is the discrete Laplacian's, 1 − (sin(k dx/2) / (k dx/2))² = 0.0505 at
// k dx = π/4, to 2% (the time step's and the Reynolds number's share).
TEST(Fluid3dKind, TaylorGreenDecaysAtTheDiscreteLaplaciansRate) {
  const Fluid3dKind kind;
  Params p = with(kind, periodicTaylorGreen(8));
  p["slice_normal"] = std::string("z");
  ASSERT_EQ(kind.validate(p), "");
  const Result r = kind.run(p);
  const double half = std::numbers::pi / 8, expected = 1.0 - std::pow(std::sin(half) / half, 2);
  EXPECT_NEAR(r.metrics.at("decay_rate_error").value, expected, 0.02 * expected);
  EXPECT_LT(r.metrics.at("max_divergence_rel").value, 1e-14);
  EXPECT_EQ(r.metrics.at("steps").value, 10);
  const std::vector<double>& t = r.timeseries.at("time_s").values;
  ASSERT_EQ(t.size(), 3u);
  for (int f = 0; f < 3; ++f) EXPECT_NEAR(t[f], 0.5 * f, 1e-12);
  EXPECT_EQ(r.timeseries.at("kinetic_energy_error_rel").values.size(), 3u);
  // The plane z = 4.5 dx: 8 × 8 cells of six fields in three frames.
  EXPECT_EQ(r.fields.nx, 8);
  EXPECT_EQ(r.fields.ny, 8);
  EXPECT_EQ(r.fields.frames(), 3);
  ASSERT_EQ(r.fields.fields.size(), 6u);
  for (const auto& [name, field] : r.fields.fields) EXPECT_EQ(field.data.size(), 3u * 64u) << name;
  // Q > 0 at the vortex cores on the plane (ω_z = 2 A k sin x sin y cos z).
  const std::vector<double>& q = r.fields.fields.at("q_per_s2").data;
  EXPECT_GT(*std::max_element(q.begin(), q.end()), 0.0);
}

// The floor source of Lentine et al. 2010 §7.1: inflow at the floor, open top; the run stays
// divergence-free and its fields show the rising fluid.
TEST(Fluid3dKind, UpdraftFromAnInflowFloor) {
  const Fluid3dKind kind;
  const Params p = with(kind, {{"cells", std::int64_t(8)}, {"side_z_low", std::string("inflow")},
                               {"inflow_z_low_m_per_s", 0.02}, {"side_z_high", std::string("open")},
                               {"side_x_low", std::string("no_slip")}, {"side_x_high", std::string("no_slip")},
                               {"end_time_s", 0.5}, {"output_interval_s", 0.25}, {"kinematic_viscosity_m2_per_s", 1e-4}});
  ASSERT_EQ(kind.validate(p), "");
  const Result r = kind.run(p);
  EXPECT_LT(r.metrics.at("max_divergence_rel").value, 1e-8);  // MG-PCG to 1e-10
  const std::vector<double>& w = r.fields.fields.at("w_m_per_s").data;
  EXPECT_NEAR(w[2 * 64 + 4 * 8 + 4], 0.02, 0.01);  // last frame, the plane's centre
  EXPECT_TRUE(std::isnan(r.metrics.at("decay_rate_error").value));  // no exact flow
  const double in = 0.02 * 0.4 * 0.4;  // m³/s through the 0.4 m square floor
  EXPECT_NEAR(r.metrics.at("inflow_m3_per_s").value, in, 1e-15);
  EXPECT_NEAR(r.metrics.at("outflow_m3_per_s").value, in, 1e-8 * in);
  EXPECT_LT(r.metrics.at("flux_balance_rel").value, 1e-8);
}

// stored_fields = "volume": the whole box (frames, nz, ny, nx) in a box of unequal sides, the same steps
// and series as the plane, and its layer y = ny/2 the plane (columns x, rows z) value for value.
TEST(Fluid3dKind, VolumeHoldsThePlaneAndTheSameSeries) {
  const Fluid3dKind kind;
  Params p = with(kind, {{"cells", std::int64_t(4)}, {"domain_y_m", 0.6}, {"domain_z_m", 0.8},
                         {"side_z_low", std::string("inflow")}, {"inflow_z_low_m_per_s", 0.02},
                         {"side_z_high", std::string("open")}, {"side_x_low", std::string("no_slip")},
                         {"side_x_high", std::string("no_slip")}, {"end_time_s", 0.5}, {"output_interval_s", 0.25},
                         {"kinematic_viscosity_m2_per_s", 1e-4}});
  ASSERT_EQ(kind.validate(p), "");
  const Result plane = kind.run(p);
  p["stored_fields"] = std::string("volume");
  const Result volume = kind.run(p);
  const FieldFrames& v = volume.fields;
  ASSERT_EQ(std::vector<int>({v.frames(), v.nz, v.ny, v.nx}), std::vector<int>({3, 8, 6, 4}));
  EXPECT_EQ(v.dz_m, 0.1);
  for (const auto& [name, series] : plane.timeseries) EXPECT_EQ(series.values, volume.timeseries.at(name).values) << name;
  EXPECT_EQ(plane.metrics.at("steps").value, volume.metrics.at("steps").value);
  ASSERT_EQ(plane.fields.fields.size(), v.fields.size());
  double largest = 0;
  for (const auto& [name, field] : plane.fields.fields) {
    const std::vector<double>& all = v.fields.at(name).data;
    ASSERT_EQ(all.size(), 3u * 8 * 6 * 4) << name;
    EXPECT_EQ(v.fields.at(name).unit, field.unit);
    for (int f = 0; f < 3; ++f)
      for (int k = 0; k < 8; ++k)
        for (int i = 0; i < 4; ++i) {
          const double want = field.data[(f * 8 + k) * 4 + i];
          ASSERT_EQ(all[((f * 8 + k) * 6 + 3) * 4 + i], want) << name << " frame " << f << " k " << k << " i " << i;
          largest = std::max(largest, std::fabs(want));
        }
  }
  EXPECT_GT(largest, 0.0);
}

TEST(Fluid3dKind, BadInputIsRefusedInWords) {
  const Fluid3dKind kind;
  Params p = with(kind, periodicTaylorGreen(0));
  p["domain_z_m"] = 1.0;
  p["cells_x"] = p["cells_y"] = p["cells_z"] = std::int64_t(8);
  EXPECT_NE(kind.validate(p).find("cells must be cubes"), std::string::npos) << kind.validate(p);
  p = with(kind, periodicTaylorGreen(8));
  p["side_x_low"] = std::string("no_slip");
  EXPECT_NE(kind.validate(p).find("periodic on one side only"), std::string::npos) << kind.validate(p);
  p["side_x_high"] = std::string("no_slip");
  EXPECT_NE(kind.validate(p).find("needs periodic sides"), std::string::npos) << kind.validate(p);
  p = with(kind, {{"side_z_low", std::string("inflow")}});
  EXPECT_NE(kind.validate(p).find("needs an open side"), std::string::npos) << kind.validate(p);
  p = with(kind, {{"output_interval_s", 2.0}});
  EXPECT_NE(kind.validate(p).find("output_interval_s"), std::string::npos);
}

// A step too long for upwind2_rk2's CFL bound ends the run as a RunFailure holding the first frame.
TEST(Fluid3dKind, BlowUpKeepsTheFramesBeforeIt) {
  const Fluid3dKind kind;
  Params p = with(kind, periodicTaylorGreen(8));
  p["amplitude_m_per_s"] = 10.0;
  p["dt_s"] = 0.5;
  p["advection"] = std::string("upwind2_rk2");
  try {
    kind.run(p);
    FAIL() << "expected a RunFailure";
  } catch (const RunFailure& e) {
    EXPECT_NE(std::string(e.what()).find("CFL number"), std::string::npos) << e.what();
    EXPECT_EQ(e.partial().timeseries.at("time_s").values, std::vector<double>{0.0});
    EXPECT_EQ(e.partial().fields.frames(), 1);
  }
}

}  // namespace
}  // namespace creaturelab::kinds
