#include "kinds/membrane.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>
#include <string>

#include "fluid/fluid_solver2.hpp"
#include "ib/coupling.hpp"
#include "ib/membrane_body.hpp"
#include "ib/membrane_run.hpp"
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

// The recorded series and marker frames.
void addMembraneRun(Result& result, const ib::MembraneRunRecorder& recorder, int markers) {
  for (const auto& s : recorder.series()) result.timeseries[s.name] = {s.values, s.unit};
  Tracks& tracks = result.lagrangian["markers_m"];
  tracks.points = markers;
  tracks.dim = 2;
  tracks.time_s = recorder.markerTimes();
  tracks.data = recorder.markerData();
}

// Why the coupled step failed, with the coupling and a hint for the stiff explicit one.
std::string membraneFailure(const ParamReader& r, double t_s, const std::exception& e) {
  std::ostringstream message;
  message << "membrane at t = " << t_s << " s (dt_s = " << r.real("dt_s") << ", "
          << (r.boolean("semi_implicit") ? "semi-implicit" : "explicit") << " coupling): " << e.what();
  if (!r.boolean("semi_implicit")) message << " The explicit coupling is stiff: try semi_implicit = true or a smaller dt_s.";
  return message.str();
}

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
  const auto& x = coupling.markers_m();
  ib::MembraneRunRecorder recorder(body, x, steps);
  recorder.frame(0.0, x, fluid);
  try {
    for (long step = 1; step <= steps; ++step) {
      recorder.step(step, coupling.step(dt), x, fluid.grid().dx_m);
      if (step % steps_per_frame == 0 || step == steps) recorder.frame(fluid.time_s(), x, fluid);
    }
  } catch (const std::exception& e) {
    Result partial;
    addMembraneRun(partial, recorder, mp.markers);
    throw RunFailure(membraneFailure(r, fluid.time_s(), e), partial);
  }
  Result result;
  addMembraneRun(result, recorder, mp.markers);
  for (const auto& m : recorder.measure(x, fluid, dt)) result.metrics[m.name] = {m.value, m.unit};
  return result;
}

}  // namespace creaturelab::kinds
