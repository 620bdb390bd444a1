#include "ib/membrane_run.hpp"

#include <algorithm>
#include <cmath>

namespace creaturelab::ib {

double laplacePressureRatio(const fluid::MacGrid2& g, const PolygonShape& shape, double tension_n_per_m) {
  const double radius = std::sqrt(std::fabs(shape.area_m2) / M_PI);
  double inside = 0, outside = 0;
  long n_in = 0, n_out = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const fluid::Vec2 c = g.cellCentre_m(i, j);
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

double energyExcess(const MembraneBody& body, std::span<const fluid::Vec2> x, double area_m2) {
  const double least = 2.0 * body.stiffness_n_per_m() * std::fabs(area_m2) * std::tan(M_PI / body.markerCount());
  return body.elasticEnergy(x) / least - 1.0;
}

MembraneRunRecorder::MembraneRunRecorder(const MembraneBody& body, std::span<const fluid::Vec2> x0, long steps)
    : body_(body), start_(polygonShape(x0)), steps_(steps), half_step_(steps / 2), area_half_(start_.area_m2) {
  for (std::size_t k = 0; k < x0.size(); ++k) {
    const auto& q = x0[(k + 1) % x0.size()];
    max_spacing_m_ = std::max(max_spacing_m_, std::hypot(q.x - x0[k].x, q.y - x0[k].y));
  }
  series_ = {{"time_s", "s", {}},
             {"area_m2", "m^2", {}},
             {"area_loss_fraction", "", {}},
             {"aspect_ratio", "", {}},
             {"elastic_energy_j_per_m", "J/m", {}},
             {"energy_excess", "", {}},
             {"kinetic_energy_j_per_m", "J/m", {}}};
}

void MembraneRunRecorder::frame(double t_s, std::span<const fluid::Vec2> x, const fluid::FluidSolver2& fluid) {
  const PolygonShape shape = polygonShape(x);
  const double values[] = {t_s,
                           shape.area_m2,
                           1.0 - shape.area_m2 / start_.area_m2,
                           shape.aspect_ratio,
                           body_.elasticEnergy(x),
                           energyExcess(body_, x, shape.area_m2),
                           fluid.kineticEnergy_joule_per_m()};
  for (std::size_t s = 0; s < series_.size(); ++s) series_[s].values.push_back(values[s]);
  for (const auto& p : x) marker_data_.insert(marker_data_.end(), {p.x, p.y});
}

void MembraneRunRecorder::step(long step, const CouplingStepReport& report, std::span<const fluid::Vec2> x,
                               double dx_m) {
  max_cfl_ = std::max(max_cfl_, report.fluid.cfl_number);
  max_speed_ = std::max(max_speed_, report.max_marker_speed_m_per_s);
  max_div_ = std::max(max_div_, report.fluid.max_divergence_per_s);
  if (report.fluid.max_velocity_component_m_per_s > 0)
    max_div_rel_ = std::max(max_div_rel_, report.fluid.max_divergence_per_s * dx_m /
                                              report.fluid.max_velocity_component_m_per_s);
  if (step == half_step_) area_half_ = polygonShape(x).area_m2;
}

std::vector<core::NamedValue> MembraneRunRecorder::measure(std::span<const fluid::Vec2> x,
                                                          const fluid::FluidSolver2& fluid, double dt_s) const {
  const PolygonShape end = polygonShape(x);
  const double late_time = fluid.time_s() - half_step_ * dt_s;
  const double late_rate = late_time > 0 ? (area_half_ - end.area_m2) / (start_.area_m2 * late_time) : std::nan("");
  return {
      {"area_loss_fraction", "", 1.0 - end.area_m2 / start_.area_m2},
      {"late_area_loss_rate_per_s", "1/s", late_rate},
      {"aspect_ratio_initial", "", start_.aspect_ratio},
      {"aspect_ratio_final", "", end.aspect_ratio},
      {"energy_excess_final", "", energyExcess(body_, x, end.area_m2)},
      {"laplace_pressure_ratio", "", laplacePressureRatio(fluid.grid(), end, body_.meanTension(x))},
      {"max_marker_spacing_cells", "", max_spacing_m_ / fluid.grid().dx_m},
      {"max_divergence", "1/s", max_div_},
      {"max_divergence_rel", "", max_div_rel_},
      {"max_cfl", "", max_cfl_},
      {"max_marker_speed_m_per_s", "m/s", max_speed_},
      {"steps", "", double(steps_)},
  };
}

}  // namespace creaturelab::ib
