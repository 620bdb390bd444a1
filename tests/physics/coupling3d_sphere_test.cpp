// Physics of the 3-D coupling (coupling3d/rigid_fluid_coupling3.hpp):
//  - Stokes drag of a periodic simple-cubic array of fixed spheres driven by a uniform body force,
//    against the drag factor K(c) of Hasimoto 1959 (J. Fluid Mech. 5, 317) as extended by Sangani &
//    Acrivos 1982 (Int. J. Multiphase Flow 8, 343, Eq. 4.3; Zick & Homsy 1982, J. Fluid Mech. 115,
//    Table 2, agree with it to the digits shown for c ≤ 0.2),
//        F = 6π μ a U K(c),  1/K = 1 − 1.7601 c^⅓ + c − 1.5593 c² + 3.9799 c^{8/3} − 3.0734 c^{10/3},
//    with c = (4/3)π a³ / L³ the volume fraction and U the mean (superficial) velocity over the cell.
//    At steady state the force on the sphere equals the body force on the whole cell, ρ g L³
//    (momentum), so the grid measures U.
//  - the leak: a sphere moving through a closed box: no net flow through its surface, and the fluid
//    inside it moves with it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "../unit/coupling3d_scenes.hpp"
#include "moving_sphere3.hpp"
#include "coupling3d/rigid_fluid_coupling3.hpp"

namespace creaturelab::coupling3d {
namespace {

constexpr double kPi = std::numbers::pi;

// Sangani & Acrivos 1982, Eq. 4.3 (simple cubic array): K(c) = F / (6π μ a U).
double dragFactor(double c) {
  const double s = std::cbrt(c);
  return 1.0 / (1 - 1.7601 * s + c - 1.5593 * c * c + 3.9799 * std::pow(s, 8) - 3.0734 * std::pow(s, 10));
}

struct ArrayDrag {
  double K = 0;            // F / (6π μ a U) measured
  double K_reference = 0;  // dragFactor(c)
  double change = 0;       // relative change of U over the last step (steady when small)
  int steps = 0;
  int iterations = 0;      // CG iterations of the last step
};

// The periodic cell of side 1 m with a sphere of radius `radius_m` at its centre, n³ cells, ν = 1 m²/s,
// ρ = 1 kg/m³, g = 1 m/s² along x, Stokes flow (advection off), stepped by dt until U changes by
// less than `steady` per step.
ArrayDrag arrayDrag(const std::filesystem::path& dir, int n, double radius_m, double dt_s, double steady,
                    int max_steps, Forcing3 forcing, bool viscous = true, double spacing_cells = 0.5,
                    double tolerance = 1e-7, double regularisation = 1e-3,
                    double retraction_cells = 0.0) {
  const auto model = testing::loadScene(dir, "sphere_" + std::to_string(n),
                                        "<geom type=\"sphere\" size=\"" + std::to_string(radius_m) +
                                            "\" pos=\"0.5 0.5 0.5\"/>",
                                        dt_s);
  rigid::RigidData data(model);
  data.kinematics();
  fluid3d::FluidParams3 f = testing::cube(n, 1.0, fluid3d::Boundaries3::allPeriodic(), 1.0);
  f.density_kg_per_m3 = 1.0;
  f.body_acceleration_m_per_s2 = {1.0, 0.0, 0.0};
  f.blowup_speed_m_per_s = 1e6;
  RigidFluidParams3 p;
  p.forcing = forcing;
  p.viscosity_in_forcing = viscous;
  p.forcing_tolerance = tolerance;
  p.forcing_regularisation = regularisation;
  p.max_forcing_iterations = 1000;
  p.marker_spacing_cells = spacing_cells;
  p.marker_retraction_cells = retraction_cells;
  RigidFluidCoupling3 c(data, f, p);
  c.fluid().stages().advection = false;
  ArrayDrag out;
  double U = 0;
  const fluid3d::Array3& u = c.fluid().grid().velocity_m_per_s[0];
  for (out.steps = 1; out.steps <= max_steps; ++out.steps) {
    c.advanceFluid(dt_s);
    c.forceFluid(data, dt_s);
    double sum = 0;
    for (std::size_t t = 0; t < u.size(); ++t) sum += u.data()[t];
    const double U_new = sum / static_cast<double>(u.size());
    out.change = std::abs(U_new - U) / std::abs(U_new);
    U = U_new;
    if (out.change < steady) break;
  }
  out.iterations = c.forcingIterations();
  const double c_volume = 4.0 / 3.0 * kPi * radius_m * radius_m * radius_m;
  out.K = 1.0 / (6 * kPi * radius_m * U);  // F = ρ g L³ = 1 N, μ = 1 Pa s
  out.K_reference = dragFactor(c_volume);
  return out;
}

class Coupling3Physics : public ::testing::Test {
 protected:
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_ = testing::scratch("physics");
};

struct Leak {
  double interior = 0;  // |mean u − V| / |V| inside the sphere
  double flux = 0;      // |Σ_k (I u)_k · n_k dA_k| / (|V| π r²): net flow out through the marker surface
  int markers = 0;
};

// The leak scene (moving_sphere3.hpp) in water, `steps` steps on n³ cells.
Leak sphereLeak(const std::filesystem::path& dir, int n, int steps, bool interior = true) {
  const double U = testing::MovingSphere::speed_m_per_s, r = testing::MovingSphere::radius_m;
  const auto model = testing::movingSphereModel(dir, "moving_" + std::to_string(n));
  rigid::RigidData data(model);
  data.kinematics();
  RigidFluidParams3 p;
  p.interior_markers = interior;
  RigidFluidCoupling3 c(data, testing::movingSphereBox(n), p);
  testing::moveSphere(c, data, steps);
  Leak out;
  out.markers = static_cast<int>(c.markers().size());
  out.interior = testing::interiorDeficit(c.fluid().grid(), data.bodyPosition(1));
  Transfer3 t;
  std::vector<Vec3> u;
  t.locate(c.fluid().grid(), ib::Kernel::peskin4, c.markerPosition_m());
  u.resize(c.markers().size());
  t.interpolate(c.fluid().grid().velocity_m_per_s, u);
  double flux = 0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    if (c.markers()[k].area_m2 == 0) continue;  // an interior marker
    const Vec3& x = c.markers()[k].local_m;  // the sphere's own frame: the outward normal is x / |x|
    const double len = std::hypot(x[0], x[1], x[2]);
    flux += (u[k][0] * x[0] + u[k][1] * x[1] + u[k][2] * x[2]) / len * c.markers()[k].area_m2;
  }
  out.flux = std::abs(flux) / (U * kPi * r * r);
  return out;
}

// The radius a_eff (m) of the sphere whose drag factor the measured one is, F / (6π μ U) = a_eff K(c(a_eff)):
// an immersed-boundary sphere drags like a sphere larger than its markers' by a fraction of a cell.
double effectiveRadius_m(double K_measured, double radius_m) {
  const double target = K_measured * radius_m;
  double lo = 0.5 * radius_m, hi = 1.9 * radius_m;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (mid * dragFactor(4.0 / 3.0 * kPi * mid * mid * mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The cheap grid of the drag check: 16³ cells, a = 4 cells (c = 0.065), steps of 1 s (ν dt / dx² = 256:
// each step is nearly the steady Stokes solve, the forces solved through it), until U changes by less
// than 1e-4 per step. Refined at a = L/4 (study in the commit message) the offset stays near 0.8 cells
// and K converges to the reference at first order in dx.
ArrayDrag cheapArrayDrag(const std::filesystem::path& dir, Forcing3 forcing) {
  return arrayDrag(dir, 16, 0.25, 1.0, 1e-4, 30, forcing, true, 0.5, 1e-6, RigidFluidParams3{}.forcing_regularisation);
}

// The check: the sphere drags like one 0.5 to 1.1 cells larger than its markers (measured 0.84 here;
// the kernel reaches 2 cells past each marker, and the forcing's regularisation lets the markers slip a
// little: at a tenth of the default weight the offset is 1.00).
bool dragMatchesWithinTheOffset(const ArrayDrag& d, double dx_m, double radius_m, double& offset_cells) {
  offset_cells = (effectiveRadius_m(d.K, radius_m) - radius_m) / dx_m;
  return offset_cells > 0.5 && offset_cells < 1.1;
}

TEST_F(Coupling3Physics, ArrayOfSpheresDragsAsHasimotoWithAFractionOfACellOffset) {
  const ArrayDrag d = cheapArrayDrag(dir_, Forcing3::projected);
  double offset = 0;
  EXPECT_TRUE(dragMatchesWithinTheOffset(d, 1.0 / 16, 0.25, offset))
      << "K " << d.K << " against " << d.K_reference << ": offset " << offset << " cells";
  EXPECT_LT(d.change, 1e-4) << "not steady after " << d.steps << " steps";
  std::printf("16^3, a = 4 cells: K %.4f, reference %.4f (%+.1f%%), effective radius a + %.3f dx, %d steps\n", d.K,
              d.K_reference, 100 * (d.K / d.K_reference - 1), offset, d.steps);
}

// Breaking test: the spheres not forcing the fluid, the body force accelerates it without bound and the
// drag check fails.
TEST_F(Coupling3Physics, ArrayDragCheckFailsWithoutForcing) {
  const ArrayDrag d = cheapArrayDrag(dir_, Forcing3::off);
  double offset = 0;
  EXPECT_FALSE(dragMatchesWithinTheOffset(d, 1.0 / 16, 0.25, offset)) << "K " << d.K << ", offset " << offset;
}

// The leak: after 10 steps the net flow out through the surface markers is under 1e-3 of the flux the
// sphere sweeps (measured 1.6e-4 and 1.4e-4: the CG tolerance), and the interior's mean velocity is the
// body's within 10% at 16³ (r = 4 cells) and 5% at 24³ (measured deficits 0.041 and 0.014). Without the
// interior markers the interior lags (deficit 0.57 at 16³, 0.25 at 24³, 0.14 at 32³: the surface
// markers constrain only the kernel-averaged velocity, whose reach is most of a 4-cell radius), which
// the last expectation sees (the measure can tell a leaking body).
TEST_F(Coupling3Physics, MovingSphereBarelyLeaks) {
  const Leak coarse = sphereLeak(dir_, 16, 10), fine = sphereLeak(dir_, 24, 10);
  const Leak hollow = sphereLeak(dir_, 16, 10, false);
  std::printf("leak: flux %.2e, %.2e; interior deficit %.3f, %.3f (16^3, 24^3); without interior markers %.3f\n",
              coarse.flux, fine.flux, coarse.interior, fine.interior, hollow.interior);
  EXPECT_LT(coarse.flux, 1e-3);
  EXPECT_LT(fine.flux, 1e-3);
  EXPECT_LT(coarse.interior, 0.1);
  EXPECT_LT(fine.interior, 0.05);
  EXPECT_GT(hollow.interior, 0.3);
}

// The retracted markers (RigidFluidParams3::marker_retraction_cells, Breugem 2012): 1 cell, the value at
// which the 16³ array at a = 4 cells above drags as Hasimoto's within 1%, checked on a sphere it was not
// chosen on: a = 3 cells (c = 0.028) on the same grid, its drag factor within 5% of Sangani & Acrivos's.
ArrayDrag retractedArrayDrag(const std::filesystem::path& dir, double retraction_cells) {
  return arrayDrag(dir, 16, 0.1875, 1.0, 1e-4, 30, Forcing3::projected, true, 0.5, 1e-6,
                   RigidFluidParams3{}.forcing_regularisation, retraction_cells);
}

TEST_F(Coupling3Physics, RetractedMarkersDragAsHasimotoWithin5Percent) {
  const ArrayDrag d = retractedArrayDrag(dir_, 1.0);
  EXPECT_NEAR(d.K / d.K_reference, 1.0, 0.05) << "K " << d.K << " against " << d.K_reference;
  EXPECT_LT(d.change, 1e-4) << "not steady after " << d.steps << " steps";
  std::printf("16^3, a = 3 cells, markers 1 cell inside: K %.4f, reference %.4f (%+.1f%%)\n", d.K, d.K_reference,
              100 * (d.K / d.K_reference - 1));
}

// Breaking test: the markers on the surface (no retraction), the same sphere drags like a larger one and
// the 5% check fails.
TEST_F(Coupling3Physics, DragCheckFailsWithoutRetraction) {
  const ArrayDrag d = retractedArrayDrag(dir_, 0.0);
  EXPECT_GT(std::abs(d.K / d.K_reference - 1.0), 0.05) << "K " << d.K << " against " << d.K_reference;
}

}  // namespace
}  // namespace creaturelab::coupling3d
