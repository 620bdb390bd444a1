#include "flesh/flesh_params.hpp"

#include <cmath>
#include <sstream>

namespace creaturelab::flesh {
namespace {

std::string bad(const char* field, double value, const char* expected) {
  std::ostringstream s;
  s << "flesh " << field << " = " << value << ": " << expected;
  return s.str();
}

bool positive(double x) { return std::isfinite(x) && x > 0; }
bool nonNegative(double x) { return std::isfinite(x) && x >= 0; }

}  // namespace

std::string FleshParams::validate() const {
  if (!positive(thickness_m)) return bad("thickness_m", thickness_m, "must be a positive length (m)");
  if (slices < 3) return bad("slices", slices, "must be at least 3 segments around a round geom");
  if (!nonNegative(max_edge_m)) return bad("max_edge_m", max_edge_m, "must be 0 (no refinement) or a positive length (m)");
  if (!positive(density_kg_per_m3)) return bad("density_kg_per_m3", density_kg_per_m3, "must be positive (kg/m^3)");
  if (!positive(youngs_modulus_pa)) return bad("youngs_modulus_pa", youngs_modulus_pa, "must be a positive modulus (Pa)");
  if (!nonNegative(stretch_damping_ratio))
    return bad("stretch_damping_ratio", stretch_damping_ratio, "must be >= 0 (1 = critical)");
  if (!positive(binding_hz)) return bad("binding_hz", binding_hz, "must be a positive frequency (Hz)");
  if (!nonNegative(binding_damping_ratio))
    return bad("binding_damping_ratio", binding_damping_ratio, "must be >= 0 (1 = critical)");
  if (!(cg_tolerance > 0 && cg_tolerance < 1)) return bad("cg_tolerance", cg_tolerance, "must lie in (0, 1)");
  if (cg_max_iterations < 1) return bad("cg_max_iterations", cg_max_iterations, "must be at least 1");
  return "";
}

}  // namespace creaturelab::flesh
