#include "kinds/membrane.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>
#include <string>

#include "fluid/fluid_solver2.hpp"
#include "ib/membrane_run.hpp"

namespace creaturelab::kinds {
namespace {

// The recorded series and marker frames.
Result recorded(const ib::MembraneRunRecorder& recorder, int markers) {
  Result result;
  for (const auto& s : recorder.series()) result.timeseries[s.name] = {s.values, s.unit};
  Tracks& tracks = result.lagrangian["markers_m"];
  tracks.points = markers;
  tracks.dim = 2;
  tracks.time_s = recorder.markerTimes();
  tracks.data = recorder.markerData();
  return result;
}

// Why the coupled step failed, with the coupling and a hint for the stiff explicit one.
std::string failure(const MembraneKindParams& q, double t_s, const std::exception& e) {
  std::ostringstream message;
  message << "membrane at t = " << t_s << " s (dt_s = " << q.dt_s << ", "
          << (q.coupling.semi_implicit ? "semi-implicit" : "explicit") << " coupling): " << e.what();
  if (!q.coupling.semi_implicit) message << " The explicit coupling is stiff: try semi_implicit = true or a smaller dt_s.";
  return message.str();
}

}  // namespace

fluid::FluidParams MembraneKindParams::fluidParams() const { return fixedStepBox(fluid, dt_s); }

ib::MembraneParams MembraneKindParams::membraneParams() const {
  ib::MembraneParams m = membrane;
  m.centre_x_m = m.centre_y_m = 0.5 * fluid.domain_width_m;
  return m;
}

ib::CouplingParams MembraneKindParams::couplingParams() const {
  ib::CouplingParams c = coupling;
  c.kernel_scale = kernelScale(c.kernel, kernel_radius_m, fluid.cellSize_m()).scale;
  return c;
}

std::string MembraneKindParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  if (std::string err = fluidParams().validate(); !err.empty()) return err;
  if (std::string err = membraneParams().validate(); !err.empty()) return err;
  if (std::string err = coupling.validate(); !err.empty()) return err;
  if (std::string err = kernelScale(coupling.kernel, kernel_radius_m, fluid.cellSize_m()).error; !err.empty())
    return err;
  const double half = 0.5 * fluid.domain_width_m, dx = fluid.cellSize_m();
  const double reach = std::max(membrane.semi_axis_x_m, membrane.semi_axis_y_m);
  // The kernel's stencil must stay inside the box (ib/transfer.hpp), with room to move: 4 cells.
  if (reach + 4 * dx > half) {
    std::ostringstream out;
    out << "the membrane (largest semi-axis " << reach << " m) must stay at least 4 cells (" << 4 * dx
        << " m) from the walls of the " << 2 * half << " m box: semi-axes up to " << half - 4 * dx << " m";
    return out.str();
  }
  if (dt_s > duration_s) return "dt_s is longer than duration_s";
  if (frame_rate_hz * dt_s > 1.0) return "frame_rate_hz asks for more than one frame per step";
  return "";
}

MembraneKind::MembraneKind() {
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

Result MembraneKind::run(const Params& p) const {
  const MembraneKindParams q = readParams<MembraneKindParams>(p);
  fluid::FluidSolver2 fluid(q.fluidParams());
  const ib::MembraneParams mp = q.membraneParams();
  const ib::MembraneBody body(mp.markers, mp.stiffness_n_per_m);
  ib::ImmersedBoundary2 coupling(fluid, body, ib::ellipseMarkers(mp), q.couplingParams());
  const long steps = std::max(1L, std::lround(q.duration_s / q.dt_s));
  const long steps_per_frame = std::max(1L, std::lround(1.0 / (q.frame_rate_hz * q.dt_s)));
  const auto& x = coupling.markers_m();
  ib::MembraneRunRecorder recorder(body, x, steps);
  recorder.frame(0.0, x, fluid);
  try {
    for (long step = 1; step <= steps; ++step) {
      recorder.step(step, coupling.step(q.dt_s), x, fluid.grid().dx_m);
      if (step % steps_per_frame == 0 || step == steps) recorder.frame(fluid.time_s(), x, fluid);
    }
  } catch (const std::exception& e) {
    throw RunFailure(failure(q, fluid.time_s(), e), recorded(recorder, mp.markers));
  }
  Result result = recorded(recorder, mp.markers);
  for (const auto& m : recorder.measure(x, fluid, q.dt_s)) result.metrics[m.name] = {m.value, m.unit};
  return result;
}

}  // namespace creaturelab::kinds
