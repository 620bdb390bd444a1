#pragma once
// What the membrane test measures (Peskin 2002; Rudolf & Mould 2009 §3.2; membrane_body.hpp): per
// frame the enclosed area and its loss, the aspect ratio, the elastic energy and its excess over the
// least for the area, the fluid's kinetic energy and the markers; over the steps the largest
// divergence, CFL number and marker speed; at the end the leak, the shape and Laplace's law. No I/O:
// the kind copies them into its Result.
#include <span>
#include <string>
#include <vector>

#include "core/named_measure.hpp"
#include "fluid/fluid_solver2.hpp"
#include "ib/coupling.hpp"
#include "ib/membrane_body.hpp"

namespace creaturelab::ib {

// Laplace's law across the membrane: mean pressure of the cells whose centres lie within R/2 of
// the centroid minus that of the cells farther than 3R/2, over T / R, with R = sqrt(A / π) and T
// the mean segment tension. 1 for a circle at rest; the band between is left out, where the
// kernel smears the jump over its support. NaN when either region has no cell.
double laplacePressureRatio(const fluid::MacGrid2& g, const PolygonShape& shape, double tension_n_per_m);

// Elastic energy over the least any N-gon of the same area can have, minus 1. For zero-rest springs
// E = ½ k Σ s_i² ≥ ½ k P² / N (Cauchy-Schwarz) and P² ≥ 4 N tan(π/N) A (the isoperimetric
// inequality for N-gons), so E ≥ 2 k A tan(π/N), with equality only for the regular N-gon: 0 when
// the membrane is round AND its markers equally spaced. An ellipse of aspect ratio 1 + 2δ with
// equally spaced markers has an excess of about 3δ²/2 (its perimeter is about 2πR (1 + δ²/4) for
// R = sqrt(ab)): aspect 1.05 ↔ about 9.4e-4.
double energyExcess(const MembraneBody& body, std::span<const fluid::Vec2> x, double area_m2);

class MembraneRunRecorder {
 public:
  // `x0`: the markers at the start (m); `steps`: the steps the run will take (the late leak rate is
  // measured over the second half, from step steps / 2).
  MembraneRunRecorder(const MembraneBody& body, std::span<const fluid::Vec2> x0, long steps);

  // A series frame at t_s: the markers x (m) and the fluid.
  void frame(double t_s, std::span<const fluid::Vec2> x, const fluid::FluidSolver2& fluid);
  // After step `step` (from 1): its report, the markers after it, the grid's cell size (m).
  void step(long step, const CouplingStepReport& report, std::span<const fluid::Vec2> x, double dx_m);

  // time_s, area_m2, area_loss_fraction, aspect_ratio, elastic_energy_j_per_m, energy_excess,
  // kinetic_energy_j_per_m, one value per frame.
  const std::vector<core::NamedSeries>& series() const { return series_; }
  // The markers at the frames: frames x markers x 2, and the frames' times.
  const std::vector<double>& markerData() const { return marker_data_; }
  const std::vector<double>& markerTimes() const { return series_[0].values; }

  // The metrics at the end, from the markers x and the fluid after the last step of dt_s.
  std::vector<core::NamedValue> measure(std::span<const fluid::Vec2> x, const fluid::FluidSolver2& fluid,
                                       double dt_s) const;

 private:
  const MembraneBody& body_;
  PolygonShape start_;
  double max_spacing_m_ = 0;
  long steps_, half_step_;
  std::vector<core::NamedSeries> series_;
  std::vector<double> marker_data_;
  double max_div_ = 0, max_div_rel_ = 0, max_cfl_ = 0, max_speed_ = 0, area_half_;
};

}  // namespace creaturelab::ib
