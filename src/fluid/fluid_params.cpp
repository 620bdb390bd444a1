#include "fluid/fluid_params.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace creaturelab::fluid {
namespace {

constexpr int kMaxCellsPerSide = 16384;

std::string show(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

class Problems {
 public:
  void add(std::string sentence) { list_.push_back(std::move(sentence)); }
  void requirePositive(double value, std::string_view name, std::string_view unit) {
    if (!(std::isfinite(value) && value > 0.0)) {
      add(std::string(name) + " must be a positive number of " + std::string(unit) + " (got " + show(value) + ")");
    }
  }
  void requireFinite(double value, std::string_view name, std::string_view unit) {
    if (!std::isfinite(value)) {
      add(std::string(name) + " must be a finite number of " + std::string(unit) + " (got " + show(value) + ")");
    }
  }
  std::string joined() const {
    std::string out;
    for (const std::string& sentence : list_) {
      if (!out.empty()) out += "; ";
      out += sentence;
    }
    return out;
  }

 private:
  std::vector<std::string> list_;
};

template <typename Enum, std::size_t N>
std::optional<Enum> parse(std::string_view name, const std::array<Enum, N>& values) {
  for (Enum value : values) {
    if (to_string(value) == name) return value;
  }
  return std::nullopt;
}

}  // namespace

std::string FluidParams::validate() const {
  Problems problems;
  problems.requirePositive(domain_width_m, "domain_width_m", "metres");
  problems.requirePositive(domain_height_m, "domain_height_m", "metres");
  const bool cells_ok = cells_x >= 2 && cells_y >= 2 && cells_x <= kMaxCellsPerSide && cells_y <= kMaxCellsPerSide;
  if (cells_x < 2 || cells_x > kMaxCellsPerSide) {
    problems.add("cells_x must be between 2 and " + std::to_string(kMaxCellsPerSide) + " (got " +
                 std::to_string(cells_x) + ")");
  }
  if (cells_y < 2 || cells_y > kMaxCellsPerSide) {
    problems.add("cells_y must be between 2 and " + std::to_string(kMaxCellsPerSide) + " (got " +
                 std::to_string(cells_y) + ")");
  }
  if (cells_ok && std::isfinite(domain_width_m) && std::isfinite(domain_height_m) && domain_width_m > 0.0 &&
      domain_height_m > 0.0) {
    const double dx = domain_width_m / cells_x;
    const double dy = domain_height_m / cells_y;
    if (std::abs(dx - dy) > 1e-9 * dx) {
      const long suggested_cells_y = std::lround(domain_height_m / dx);
      problems.add("cells must be square, but domain_width_m / cells_x = " + show(dx) +
                   " m and domain_height_m / cells_y = " + show(dy) + " m; for example set cells_y = " +
                   std::to_string(suggested_cells_y) + " or domain_height_m = " + show(dx * cells_y));
    }
  }
  problems.requirePositive(density_kg_per_m3, "density_kg_per_m3", "kg/m^3");
  if (!(std::isfinite(kinematic_viscosity_m2_per_s) && kinematic_viscosity_m2_per_s >= 0.0)) {
    problems.add("kinematic_viscosity_m2_per_s must be zero or a positive number of m^2/s (got " +
                 show(kinematic_viscosity_m2_per_s) + "; water at 20 °C is 1.0e-6)");
  }
  const std::array<std::pair<const Wall*, std::string_view>, 4> walls_named{
      {{&walls.left, "left"}, {&walls.right, "right"}, {&walls.bottom, "bottom"}, {&walls.top, "top"}}};
  for (const auto& [wall, name] : walls_named) {
    const std::string key = "walls." + std::string(name) + ".tangential_velocity_m_per_s";
    problems.requireFinite(wall->tangential_velocity_m_per_s, key, "m/s");
    if (wall->type != WallType::moving && wall->type != WallType::inflow && wall->tangential_velocity_m_per_s != 0.0 &&
        std::isfinite(wall->tangential_velocity_m_per_s)) {
      problems.add(key + " = " + show(wall->tangential_velocity_m_per_s) + " has no effect on a " +
                   std::string(to_string(wall->type)) + " wall; set walls." + std::string(name) +
                   ".type = moving (or inflow) or the velocity to 0");
    }
    const std::string inflow_key = "walls." + std::string(name) + ".inflow_m_per_s";
    problems.requireFinite(wall->inflow_m_per_s, inflow_key, "m/s");
    if (wall->type != WallType::inflow && wall->inflow_m_per_s != 0.0 && std::isfinite(wall->inflow_m_per_s)) {
      problems.add(inflow_key + " = " + show(wall->inflow_m_per_s) + " has no effect on a " +
                   std::string(to_string(wall->type)) + " wall; set walls." + std::string(name) +
                   ".type = inflow or the speed to 0");
    }
  }
  if (walls.anyInflow() && walls.closed()) {
    problems.add("an inflow wall needs an open wall for the fluid to leave (with every other wall closed the "
                 "projection has no solution)");
  }
  if (!(std::isfinite(pressure_tolerance) && pressure_tolerance > 0.0 && pressure_tolerance < 1.0)) {
    problems.add("pressure_tolerance must lie between 0 and 1, exclusive (got " + show(pressure_tolerance) +
                 "; 1e-10 makes the projection exact for practical purposes)");
  }
  if (pressure_max_iterations < 1) {
    problems.add("pressure_max_iterations must be at least 1 (got " + std::to_string(pressure_max_iterations) + ")");
  }
  if (!(std::isfinite(viscosity_tolerance) && viscosity_tolerance > 0.0 && viscosity_tolerance < 1.0)) {
    problems.add("viscosity_tolerance must lie between 0 and 1, exclusive (got " + show(viscosity_tolerance) + ")");
  }
  if (threads < 1 || threads > 16) {
    problems.add("threads must be between 1 and 16 (got " + std::to_string(threads) + ")");
  }
  if (viscosity_max_iterations < 1) {
    problems.add("viscosity_max_iterations must be at least 1 (got " + std::to_string(viscosity_max_iterations) + ")");
  }
  if (!(std::isfinite(cfl_safety_factor) && cfl_safety_factor > 0.0 && cfl_safety_factor <= 10.0)) {
    problems.add("cfl_safety_factor must be above 0 and at most 10 (got " + show(cfl_safety_factor) +
                 "; 0.5 is a good default, the paper used 0.001 with the elastic body)");
  }
  if (time_step_policy == TimeStepPolicy::cfl_adaptive && cfl_safety_factor > maxStableCflNumber(advection)) {
    problems.add("cfl_safety_factor " + show(cfl_safety_factor) + " is above the stability bound " +
                 show(maxStableCflNumber(advection)) + " of advection = " + std::string(to_string(advection)));
  }
  problems.requirePositive(max_step_s, "max_step_s", "seconds");
  problems.requirePositive(fixed_step_s, "fixed_step_s", "seconds");
  problems.requireFinite(body_acceleration_x_m_per_s2, "body_acceleration_x_m_per_s2", "m/s^2");
  problems.requireFinite(body_acceleration_y_m_per_s2, "body_acceleration_y_m_per_s2", "m/s^2");
  problems.requirePositive(blowup_speed_m_per_s, "blowup_speed_m_per_s", "m/s");
  return problems.joined();
}

double maxStableCflNumber(AdvectionScheme scheme) {
  if (scheme == AdvectionScheme::upwind2_rk2) return 0.5;
  return std::numeric_limits<double>::infinity();
}

std::string_view to_string(WallType type) {
  switch (type) {
    case WallType::free_slip:
      return "free_slip";
    case WallType::no_slip:
      return "no_slip";
    case WallType::moving:
      return "moving";
    case WallType::open:
      return "open";
    case WallType::inflow:
      return "inflow";
  }
  return "unknown";
}

std::string_view to_string(AdvectionScheme scheme) {
  switch (scheme) {
    case AdvectionScheme::semi_lagrangian:
      return "semi_lagrangian";
    case AdvectionScheme::maccormack:
      return "maccormack";
    case AdvectionScheme::upwind2_rk2:
      return "upwind2_rk2";
  }
  return "unknown";
}

std::string_view to_string(PressureSolverType type) {
  switch (type) {
    case PressureSolverType::fast_direct:
      return "fast_direct";
    case PressureSolverType::pcg:
      return "pcg";
  }
  return "unknown";
}

std::string_view to_string(TimeStepPolicy policy) {
  switch (policy) {
    case TimeStepPolicy::cfl_adaptive:
      return "cfl_adaptive";
    case TimeStepPolicy::fixed:
      return "fixed";
  }
  return "unknown";
}

std::string_view to_string(ViscositySolverType type) {
  switch (type) {
    case ViscositySolverType::iterative:
      return "iterative";
    case ViscositySolverType::fast_direct:
      return "fast_direct";
  }
  return "unknown";
}

std::string_view to_string(ViscosityScheme scheme) {
  switch (scheme) {
    case ViscosityScheme::backward_euler:
      return "backward_euler";
    case ViscosityScheme::crank_nicolson:
      return "crank_nicolson";
  }
  return "unknown";
}

std::string_view to_string(ForceStage stage) {
  switch (stage) {
    case ForceStage::before_advection:
      return "before_advection";
    case ForceStage::after_advection:
      return "after_advection";
  }
  return "unknown";
}

std::optional<WallType> parseWallType(std::string_view name) {
  return parse(name,
               std::array{WallType::free_slip, WallType::no_slip, WallType::moving, WallType::open, WallType::inflow});
}
std::optional<AdvectionScheme> parseAdvectionScheme(std::string_view name) {
  return parse(name, std::array{AdvectionScheme::semi_lagrangian, AdvectionScheme::maccormack, AdvectionScheme::upwind2_rk2});
}
std::optional<PressureSolverType> parsePressureSolverType(std::string_view name) {
  return parse(name, std::array{PressureSolverType::fast_direct, PressureSolverType::pcg});
}
std::optional<TimeStepPolicy> parseTimeStepPolicy(std::string_view name) {
  return parse(name, std::array{TimeStepPolicy::cfl_adaptive, TimeStepPolicy::fixed});
}
std::optional<ViscositySolverType> parseViscositySolverType(std::string_view name) {
  return parse(name, std::array{ViscositySolverType::iterative, ViscositySolverType::fast_direct});
}

std::optional<ViscosityScheme> parseViscosityScheme(std::string_view name) {
  return parse(name, std::array{ViscosityScheme::backward_euler, ViscosityScheme::crank_nicolson});
}

std::optional<ForceStage> parseForceStage(std::string_view name) {
  return parse(name, std::array{ForceStage::before_advection, ForceStage::after_advection});
}

}  // namespace creaturelab::fluid
