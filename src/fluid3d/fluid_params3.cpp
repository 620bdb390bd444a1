#include "fluid3d/fluid_params3.hpp"

#include <cmath>
#include <sstream>
#include <vector>

namespace creaturelab::fluid3d {
namespace params3_detail {

std::string show(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

class Problems3 {
 public:
  void add(std::string sentence) { list_.push_back(std::move(sentence)); }
  void requirePositive(double value, std::string_view name, std::string_view unit) {
    if (!(std::isfinite(value) && value > 0.0))
      add(std::string(name) + " must be a positive number of " + std::string(unit) + " (got " + show(value) + ")");
  }
  std::string joined() const {
    std::string out;
    for (const std::string& sentence : list_) out += (out.empty() ? "" : "; ") + sentence;
    return out;
  }

 private:
  std::vector<std::string> list_;
};

}  // namespace params3_detail

std::string FluidParams3::validate() const {
  using params3_detail::show;
  params3_detail::Problems3 problems;
  const char* axis_names[3] = {"x", "y", "z"};
  const int cells[3] = {cells_x, cells_y, cells_z};
  const double lengths[3] = {domain_x_m, domain_y_m, domain_z_m};
  for (int a = 0; a < 3; ++a) {
    const std::string name = axis_names[a];
    if (cells[a] < 2 || cells[a] > 4096)
      problems.add("cells_" + name + " must be between 2 and 4096 (got " + std::to_string(cells[a]) + ")");
    problems.requirePositive(lengths[a], "domain_" + name + "_m", "metres");
    const AxisBoundary3& b = boundaries.axis[a];
    if ((b.low == BoundaryType3::periodic) != (b.high == BoundaryType3::periodic))
      problems.add("the " + name + " axis is periodic on one side only: make both sides periodic or neither");
    for (const double speed : {b.low_inflow_m_per_s, b.high_inflow_m_per_s})
      if (!std::isfinite(speed)) problems.add("the " + name + " axis' inflow speed must be finite (got " + show(speed) + ")");
  }
  if (projection == ProjectionScheme3::incremental && viscosity_scheme == ViscosityScheme3::crank_nicolson)
    problems.add("projection = incremental needs viscosity_scheme backward_euler or explicit_euler: with "
                 "crank_nicolson it grows unstable beside no-slip walls once nu dt / dx^2 reaches 1");
  if (boundaries.anyInflow() && boundaries.closed())
    problems.add("an inflow side needs an open side for the fluid to leave by: make one side open");
  if (problems.joined().empty()) {
    const double dx = cellSize_m();
    for (int a = 1; a < 3; ++a) {
      if (std::fabs(lengths[a] / cells[a] - dx) > 1e-9 * dx)
        problems.add(std::string("cells must be cubes: domain_") + axis_names[a] + "_m / cells_" + axis_names[a] +
                     " = " + show(lengths[a] / cells[a]) + " m differs from domain_x_m / cells_x = " + show(dx) + " m");
    }
  }
  problems.requirePositive(density_kg_per_m3, "density_kg_per_m3", "kg/m^3");
  if (!(std::isfinite(kinematic_viscosity_m2_per_s) && kinematic_viscosity_m2_per_s >= 0.0))
    problems.add("kinematic_viscosity_m2_per_s must be zero or positive (got " + show(kinematic_viscosity_m2_per_s) + ")");
  problems.requirePositive(viscosity_tolerance, "viscosity_tolerance", "(relative residual)");
  problems.requirePositive(pressure_tolerance, "pressure_tolerance", "(relative residual)");
  if (viscosity_max_iterations < 1) problems.add("viscosity_max_iterations must be at least 1");
  if (pressure_max_iterations < 1) problems.add("pressure_max_iterations must be at least 1");
  problems.requirePositive(cfl_safety_factor, "cfl_safety_factor", "(fraction of the CFL limit)");
  problems.requirePositive(max_step_s, "max_step_s", "seconds");
  problems.requirePositive(fixed_step_s, "fixed_step_s", "seconds");
  for (double g : body_acceleration_m_per_s2)
    if (!std::isfinite(g)) problems.add("body_acceleration_m_per_s2 must be finite (got " + show(g) + ")");
  if (threads < 1 || threads > 16) problems.add("threads must be between 1 and 16 (got " + std::to_string(threads) + ")");
  problems.requirePositive(blowup_speed_m_per_s, "blowup_speed_m_per_s", "m/s");
  return problems.joined();
}

std::string_view toString(BoundaryType3 type) {
  switch (type) {
    case BoundaryType3::periodic: return "periodic";
    case BoundaryType3::free_slip: return "free_slip";
    case BoundaryType3::no_slip: return "no_slip";
    case BoundaryType3::open: return "open";
    case BoundaryType3::inflow: return "inflow";
  }
  return "?";
}
std::string_view toString(AdvectionScheme3 scheme) {
  switch (scheme) {
    case AdvectionScheme3::semi_lagrangian: return "semi_lagrangian";
    case AdvectionScheme3::maccormack: return "maccormack";
    case AdvectionScheme3::upwind2_rk2: return "upwind2_rk2";
  }
  return "?";
}
std::string_view toString(PressureSolverType3 type) {
  return type == PressureSolverType3::spectral ? "spectral" : "mg_pcg";
}
std::string_view toString(ViscosityScheme3 scheme) {
  switch (scheme) {
    case ViscosityScheme3::backward_euler: return "backward_euler";
    case ViscosityScheme3::crank_nicolson: return "crank_nicolson";
    case ViscosityScheme3::explicit_euler: return "explicit_euler";
  }
  return "?";
}

std::string_view toString(ProjectionScheme3 scheme) {
  return scheme == ProjectionScheme3::incremental ? "incremental" : "non_incremental";
}

}  // namespace creaturelab::fluid3d
