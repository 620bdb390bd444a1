#include <sstream>

#include "fish/export.hpp"

namespace creaturelab::fish {

std::string exportObj(const SkinMesh& m, const std::string& comment) {
  std::ostringstream out;
  out.precision(9);
  out << "# " << comment << "\n# creaturelab fish skin: " << m.positions.size() << " vertices, " << m.triangles.size()
      << " triangles\n";
  for (const auto& p : m.positions) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& n : m.normals) out << "vn " << n.x() << ' ' << n.y() << ' ' << n.z() << '\n';
  for (const auto& t : m.triangles)
    out << "f " << t[0] + 1 << "//" << t[0] + 1 << ' ' << t[1] + 1 << "//" << t[1] + 1 << ' ' << t[2] + 1 << "//"
        << t[2] + 1 << '\n';
  return out.str();
}

}  // namespace creaturelab::fish
