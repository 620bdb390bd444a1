#include "kinds/membrane.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <span>
#include <sstream>
#include <string>

#include "fluid/fluid_solver2.hpp"
#include "ib/coupling.hpp"
#include "ib/membrane_body.hpp"
#include "kinds/ib_params.hpp"

namespace creaturelab::kinds {
namespace {

ib::MembraneParams membraneParams(const ParamReader& r) {
  ib::MembraneParams m;
  m.centre_x_m = m.centre_y_m = 0.5 * r.real("domain_m");
  m.semi_axis_x_m = r.real("semi_axis_x_m");
  m.semi_axis_y_m = r.real("semi_axis_y_m");
  m.markers = int(r.integer("markers"));
  m.stiffness_n_per_m = r.real("stiffness_n_per_m");
  return m;
}

// Laplace's law across the membrane: mean pressure of the cells whose centres lie within R/2 of
// the centroid minus that of the cells farther than 3R/2, over T / R, with R = sqrt(A / π) and T
// the mean segment tension. 1 for a circle at rest; the band between is left out, where the
// kernel smears the jump over its support.
double laplacePressureRatio(const fluid::MacGrid2& g, const ib::PolygonShape& shape, double tension_n_per_m) {
  const double radius = std::sqrt(std::fabs(shape.area_m2) / M_PI);
  double inside = 0, outside = 0;
  long n_in = 0, n_out = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const fluid::Vec2 c = g.cell_centre_m(i, j);
      const double d = std::hypot(c.x - shape.centroid_m.x, c.y - shape.centroid_m.y);
      if (d < 0.5 * radius) {
        inside += g.pressure_pa(i, j);
        ++n_in;
      } else if (d > 1.5 * radius) {
        outside += g.pressure_pa(i, j);
        ++n_out;
      }
    }
  if (n_in == 0 || n_out == 0) return std::nan("");
  return (inside / double(n_in) - outside / double(n_out)) / (tension_n_per_m / radius);
}

// Elastic energy over the least any N-gon of the same area can have, minus 1. For zero-rest springs
// E = ½ k Σ s_i² ≥ ½ k P² / N (Cauchy-Schwarz) and P² ≥ 4 N tan(π/N) A (the isoperimetric
// inequality for N-gons), so E ≥ 2 k A tan(π/N), with equality only for the regular N-gon: 0 when
// the membrane is round AND its markers equally spaced. An ellipse of aspect ratio 1 + 2δ with
// equally spaced markers has an excess of about 3δ²/2 (its perimeter is about 2πR (1 + δ²/4) for
// R = sqrt(ab)): aspect 1.05 ↔ about 9.4e-4.
double energyExcess(const ib::MembraneBody& body, std::span<const fluid::Vec2> x, double area_m2) {
  const double least = 2.0 * body.stiffness_n_per_m() * std::fabs(area_m2) * std::tan(M_PI / body.markerCount());
  return body.elasticEnergy(x) / least - 1.0;
}

// Series and marker frames; plain data the runner writes.
class Recorder {
 public:
  Recorder(Result& result, int markers, double area0_m2) : area0_m2_(area0_m2) {
    time_ = &(result.timeseries["time_s"] = {{}, "s"});
    area_ = &(result.timeseries["area_m2"] = {{}, "m^2"});
    loss_ = &(result.timeseries["area_loss_fraction"] = {{}, ""});
    aspect_ = &(result.timeseries["aspect_ratio"] = {{}, ""});
    elastic_ = &(result.timeseries["elastic_energy_j_per_m"] = {{}, "J/m"});
    excess_ = &(result.timeseries["energy_excess"] = {{}, ""});
    kinetic_ = &(result.timeseries["kinetic_energy_j_per_m"] = {{}, "J/m"});
    markers_ = &result.lagrangian["markers_m"];
    markers_->points = markers;
    markers_->dim = 2;
  }
  void frame(double t_s, const std::vector<fluid::Vec2>& x, const ib::MembraneBody& body,
             const fluid::FluidSolver2& fluid) {
    const ib::PolygonShape shape = ib::polygonShape(x);
    time_->values.push_back(t_s);
    area_->values.push_back(shape.area_m2);
    loss_->values.push_back(1.0 - shape.area_m2 / area0_m2_);
    aspect_->values.push_back(shape.aspect_ratio);
    elastic_->values.push_back(body.elasticEnergy(x));
    excess_->values.push_back(energyExcess(body, x, shape.area_m2));
    kinetic_->values.push_back(fluid.kinetic_energy_joule_per_m());
    markers_->time_s.push_back(t_s);
    for (const auto& p : x) markers_->data.insert(markers_->data.end(), {p.x, p.y});
  }

 private:
  double area0_m2_;
  Series *time_, *area_, *loss_, *aspect_, *elastic_, *excess_, *kinetic_;
  Tracks* markers_;
};

}  // namespace

MembraneKind::MembraneKind() {
  // --- coupling (ib/coupling.hpp; Rudolf & Mould 2009 §3.2)
  params_ = couplingSpecs({
      .kernel = "bilinear",
      .kernel_doc = "spreading/interpolation: the jellyfish paper's bilinear 4-face stencil or Peskin's 4-point kernel",
      .mobility_doc = "fluid response assumed by the semi-implicit force: through the markers' stencils, or each "
                      "marker alone (ib/coupling.hpp)",
      .kernel_radius_doc = "radius of the kernel's support; 0 = the grid's own (1 cell bilinear, 2 peskin4), else a "
                           "whole multiple of that (ib/kernel.hpp)",
      .implicit_theta = 1.0,
      .implicit_theta_doc = "The membrane test compares 0.5 with it",
  });
  // --- fluid: a viscous liquid in a free-slip box (the test is of the method, not of sea water)
  const std::vector<ParamSpec> fluid_specs = fluidBoxSpecs({
      .domain_m = 1.0,
      .domain_doc = "side of the square free-slip box",
      .cells_doc = "fluid cells per side (the jellyfish paper's grids: 50 and 100)",
      .density_doc = "fluid density",
      .kinematic_viscosity_m2_per_s = 1e-2,
      .viscosity_doc = "nu; 1e-2 (10 000 x water) damps the relaxation within a few seconds",
      .advection_doc = "velocity advection: semi-Lagrangian (Stam 1999, the jellyfish paper's), MacCormack or upwind2_rk2",
  });
  const std::vector<ParamSpec> rest = {
      // --- membrane (ib/membrane_body.hpp)
      real("semi_axis_x_m", 0.25, "m", 1e-6, 100, "initial ellipse's semi-axis along x (centred in the box)"),
      real("semi_axis_y_m", 0.15, "m", 1e-6, 100, "initial ellipse's semi-axis along y"),
      integer("markers", 256, 3, 100000,
              "markers, equally spaced on the ellipse; keep them < dx/2 apart (gaps of 1-2 cells leak)"),
      real("stiffness_n_per_m", 2000.0, "N/m^2", 1e-12, 1e12,
           "zero-rest-length spring constant, N/m per metre of depth; tension = k x segment length"),
      // --- stepping and output
      real("dt_s", 0.01, "s", 1e-7, 1, "coupled step (fixed)"),
      real("duration_s", 5.0, "s", 1e-6, 1e6, "simulated time"),
      real("blowup_speed_m_per_s", 10.0, "m/s", 1e-6, 1e6,
           "fluid speed taken as a blow-up (about 200x the default relaxation flow)"),
      real("frame_rate_hz", 10.0, "Hz", 1e-3, 1e4, "series and marker frames per second"),
  };
  for (const auto* specs : {&fluid_specs, &rest}) params_.insert(params_.end(), specs->begin(), specs->end());
  metrics_ = {
      {"area_loss_fraction", "", "1 - final enclosed area / initial enclosed area (polygon of the markers)"},
      {"late_area_loss_rate_per_s", "1/s", "area lost over the second half of the run, per initial area per second"},
      {"aspect_ratio_initial", "", "sqrt of the ratio of the enclosed area's principal second moments (a/b)"},
      {"aspect_ratio_final", "", "the same at the end (1 for a circle)"},
      {"energy_excess_final", "", "elastic energy at the end over the least of any N-gon of the same area, minus 1"},
      {"laplace_pressure_ratio", "", "pressure jump inside/outside at the end over T/R (Laplace's law: 1)"},
      {"max_marker_spacing_cells", "", "largest initial distance between neighbouring markers, in cells"},
      {"max_divergence", "1/s", "largest max|div u| after any step"},
      {"max_divergence_rel", "", "largest max|div u| dx / max|u| after any step"},
      {"max_cfl", "", "largest max(|u|,|v|) dt / dx of any step"},
      {"max_marker_speed_m_per_s", "m/s", "largest marker speed of any step"},
      {"steps", "", "coupled steps taken"},
  };
}

std::string MembraneKind::doc() const {
  return "an elliptical elastic membrane relaxing to a circle in a box of fluid: the immersed boundary's area leak "
         "(Peskin 2002; Rudolf & Mould 2009 §3.2)";
}

std::string MembraneKind::validate(const Params& p) const {
  ParamReader r(p);
  if (std::string err = fluidBoxParams(r).validate(); !err.empty()) return err;
  if (std::string err = membraneParams(r).validate(); !err.empty()) return err;
  if (std::string err = kernelScale(r).error; !err.empty()) return err;
  const double half = 0.5 * r.real("domain_m");
  const double dx = r.real("domain_m") / double(r.integer("cells"));
  const double reach = std::max(r.real("semi_axis_x_m"), r.real("semi_axis_y_m"));
  // The kernel's stencil must stay inside the box (ib/transfer.hpp), with room to move: 4 cells.
  if (reach + 4 * dx > half) {
    std::ostringstream out;
    out << "the membrane (largest semi-axis " << reach << " m) must stay at least 4 cells (" << 4 * dx
        << " m) from the walls of the " << 2 * half << " m box: semi-axes up to " << half - 4 * dx << " m";
    return out.str();
  }
  if (r.real("dt_s") > r.real("duration_s")) return "dt_s is longer than duration_s";
  if (r.real("frame_rate_hz") * r.real("dt_s") > 1.0) return "frame_rate_hz asks for more than one frame per step";
  return "";
}

Result MembraneKind::run(const Params& p) const {
  ParamReader r(p);
  fluid::FluidSolver2 fluid(fluidBoxParams(r));
  const ib::MembraneParams mp = membraneParams(r);
  const ib::MembraneBody body(mp.markers, mp.stiffness_n_per_m);
  ib::ImmersedBoundary2 coupling(fluid, body, ib::ellipseMarkers(mp), couplingParams(r));

  const double dt = r.real("dt_s");
  const long steps = std::max(1L, std::lround(r.real("duration_s") / dt));
  const long steps_per_frame = std::max(1L, std::lround(1.0 / (r.real("frame_rate_hz") * dt)));
  const long half_step = steps / 2;

  const auto& x = coupling.markers_m();
  const ib::PolygonShape start = ib::polygonShape(x);
  double max_spacing = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const auto& q = x[(k + 1) % x.size()];
    max_spacing = std::max(max_spacing, std::hypot(q.x - x[k].x, q.y - x[k].y));
  }

  Result result;
  Recorder recorder(result, mp.markers, start.area_m2);
  recorder.frame(0.0, x, body, fluid);

  double max_div = 0, max_div_rel = 0, max_cfl = 0, max_speed = 0, area_half = start.area_m2;
  try {
    for (long step = 1; step <= steps; ++step) {
      const ib::CouplingStepReport report = coupling.step(dt);
      max_cfl = std::max(max_cfl, report.fluid.cfl_number);
      max_speed = std::max(max_speed, report.max_marker_speed_m_per_s);
      max_div = std::max(max_div, report.fluid.max_divergence_per_s);
      if (report.fluid.max_velocity_component_m_per_s > 0)
        max_div_rel = std::max(max_div_rel, report.fluid.max_divergence_per_s * fluid.grid().dx_m /
                                                report.fluid.max_velocity_component_m_per_s);
      if (step == half_step) area_half = ib::polygonShape(x).area_m2;
      if (step % steps_per_frame == 0 || step == steps) recorder.frame(fluid.time_s(), x, body, fluid);
    }
  } catch (const std::exception& e) {
    std::ostringstream message;
    message << "membrane at t = " << fluid.time_s() << " s (dt_s = " << dt << ", "
            << (r.boolean("semi_implicit") ? "semi-implicit" : "explicit") << " coupling): " << e.what();
    if (!r.boolean("semi_implicit"))
      message << " The explicit coupling is stiff: try semi_implicit = true or a smaller dt_s.";
    throw RunFailure(message.str(), result);
  }

  const ib::PolygonShape end = ib::polygonShape(x);
  const double late_time = fluid.time_s() - half_step * dt;
  auto& m = result.metrics;
  m["area_loss_fraction"] = {1.0 - end.area_m2 / start.area_m2, ""};
  const double late_rate = late_time > 0 ? (area_half - end.area_m2) / (start.area_m2 * late_time) : std::nan("");
  m["late_area_loss_rate_per_s"] = {late_rate, "1/s"};
  m["aspect_ratio_initial"] = {start.aspect_ratio, ""};
  m["aspect_ratio_final"] = {end.aspect_ratio, ""};
  m["energy_excess_final"] = {energyExcess(body, x, end.area_m2), ""};
  m["laplace_pressure_ratio"] = {laplacePressureRatio(fluid.grid(), end, body.meanTension(x)), ""};
  m["max_marker_spacing_cells"] = {max_spacing / fluid.grid().dx_m, ""};
  m["max_divergence"] = {max_div, "1/s"};
  m["max_divergence_rel"] = {max_div_rel, ""};
  m["max_cfl"] = {max_cfl, ""};
  m["max_marker_speed_m_per_s"] = {max_speed, "m/s"};
  m["steps"] = {double(steps), ""};
  return result;
}

}  // namespace creaturelab::kinds
