#include <sstream>

#include "fish/export.hpp"

namespace creaturelab::fish {

std::string exportPov(const SkinMesh& m, const Eigen::Vector3d& c, double L, const std::string& comment) {
  std::ostringstream out;
  out.precision(9);
  // POV-Ray is left-handed with y up: our (x, y, z) with z up is written as <x, z, y>.
  auto vec = [&](const Eigen::Vector3d& v) {
    std::ostringstream s;
    s.precision(9);
    s << '<' << v.x() << ", " << v.z() << ", " << v.y() << '>';
    return s.str();
  };
  out << "// " << comment << "\n#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      << "background { rgb <0.05, 0.22, 0.35> }\n"
      << "camera { perspective location " << vec(c + Eigen::Vector3d(0.2 * L, 0.55 * L, 1.0 * L)) << " look_at "
      << vec(c) << " angle 50 right x*image_width/image_height }\n"
      << "light_source { " << vec(c + Eigen::Vector3d(0.5 * L, 1.5 * L, 3 * L)) << " color rgb <1, 1, 0.95> }\n"
      << "light_source { " << vec(c + Eigen::Vector3d(-2 * L, -1 * L, 1 * L)) << " color rgb <0.3, 0.35, 0.45> shadowless }\n"
      << "plane { y, " << c.z() - 0.4 * L << " pigment { checker rgb <0.75, 0.7, 0.55>, rgb <0.65, 0.6, 0.45> scale "
      << 0.25 * L << " } finish { ambient 0.15 } }\n";
  out << "mesh2 {\n  vertex_vectors { " << m.positions.size();
  for (const auto& p : m.positions) out << ",\n    " << vec(p);
  out << "\n  }\n  normal_vectors { " << m.normals.size();
  for (const auto& n : m.normals) out << ",\n    " << vec(n);
  out << "\n  }\n  face_indices { " << m.triangles.size();
  for (const auto& t : m.triangles) out << ",\n    <" << t[0] << ", " << t[1] << ", " << t[2] << '>';
  out << "\n  }\n  pigment { gradient y color_map { [0 rgb <0.85, 0.82, 0.7>] [1 rgb <0.25, 0.45, 0.6>] } scale "
      << 0.5 * L << " translate <0, " << c.z() - 0.25 * L << ", 0> }\n"
      << "  finish { ambient 0.2 diffuse 0.7 specular 0.4 roughness 0.02 }\n}\n";
  return out.str();
}

}  // namespace creaturelab::fish
