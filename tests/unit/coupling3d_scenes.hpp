#pragma once
// MuJoCo scenes and fluid boxes shared by the coupling3d tests.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "fluid3d/fluid_params3.hpp"
#include "rigid/rigid_model.hpp"

namespace creaturelab::coupling3d::testing {

/// Writes an MJCF body list into a model (no gravity, no contacts, timestep dt) and loads it.
inline rigid::RigidModel loadScene(const std::filesystem::path& dir, const std::string& name, const std::string& bodies,
                                   double dt_s) {
  const std::filesystem::path path = dir / (name + ".xml");
  std::ofstream(path) << "<mujoco><option timestep=\"" << dt_s << "\" gravity=\"0 0 0\"/>"
                      << "<default><geom contype=\"0\" conaffinity=\"0\"/></default><worldbody>" << bodies
                      << "</worldbody></mujoco>";
  return rigid::RigidModel::load(path.string());
}

/// A cubic box of n³ cells and side `side_m`, water-like (ρ = 1000 kg/m³), the exact pressure solve.
inline fluid3d::FluidParams3 cube(int n, double side_m, const fluid3d::Boundaries3& sides, double nu_m2_per_s) {
  fluid3d::FluidParams3 f;
  f.domain_x_m = f.domain_y_m = f.domain_z_m = side_m;
  f.cells_x = f.cells_y = f.cells_z = n;
  f.boundaries = sides;
  f.kinematic_viscosity_m2_per_s = nu_m2_per_s;
  f.pressure_solver = fluid3d::PressureSolverType3::spectral;
  return f;
}

/// A fresh folder for one test's files.
inline std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("coupling3d_" + name + "_" +
                                                                              std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace creaturelab::coupling3d::testing
