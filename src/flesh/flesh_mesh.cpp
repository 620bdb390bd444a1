#include "flesh/flesh_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include <Eigen/Geometry>

#include "rigid/geom_surface.hpp"
#include "rigid/rigid_data.hpp"

namespace creaturelab::flesh {
namespace {

// The most vertices one geom's refined surface may take (a few hundred megabytes of work space).
constexpr std::size_t kMaxVerticesPerGeom = 200000;

using V3 = Eigen::Vector3d;

// One geom's surface with shared vertices.
struct Indexed {
  std::vector<V3> x;
  std::vector<std::array<int, 3>> tri;
};

// Welds the triangle soup of geomSurfaces: points closer than 1e-9 m (the seam of a solid of
// revolution, sin(2 pi) != 0) become one vertex.
Indexed weld(const std::vector<rigid::Triangle>& soup) {
  Indexed out;
  std::map<std::tuple<long long, long long, long long>, int> index;
  auto vertex = [&](const rigid::Vec3& p) {
    const double q = 1e-9;
    const auto key = std::make_tuple(std::llround(p[0] / q), std::llround(p[1] / q), std::llround(p[2] / q));
    const auto [it, added] = index.try_emplace(key, int(out.x.size()));
    if (added) out.x.emplace_back(p[0], p[1], p[2]);
    return it->second;
  };
  for (const rigid::Triangle& t : soup) {
    const std::array<int, 3> f{vertex(t.a), vertex(t.b), vertex(t.c)};
    if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2]) out.tri.push_back(f);
  }
  return out;
}

std::vector<V3> vertexNormals(const std::vector<V3>& x, const std::vector<std::array<int, 3>>& tri);

// Longest edge of the surface offset by t along its vertex normals (the flesh's own edges).
double longestOffsetEdge(const Indexed& m, double t) {
  const std::vector<V3> n = vertexNormals(m.x, m.tri);
  double longest = 0;
  for (const auto& f : m.tri)
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      longest = std::max(longest, (m.x[a] + t * n[a] - m.x[b] - t * n[b]).norm());
    }
  return longest;
}

// Bisects the longest edge of the surface, in both triangles that share it (so the surface stays
// closed and keeps its orientation), until no edge is longer than max_edge. The longest first, so a
// long thin quad of a capsule's side is cut across its length rather than into slivers. Midpoints stay
// on the flat triangles: refinement adds vertices, not roundness.
Indexed bisectLongEdges(Indexed m, double max_edge) {
  using Edge = std::pair<int, int>;
  std::map<Edge, std::vector<int>> faces;  // edge (low, high) -> triangles using it
  auto attach = [&](int f) {
    for (int k = 0; k < 3; ++k) faces[std::minmax(m.tri[f][k], m.tri[f][(k + 1) % 3])].push_back(f);
  };
  auto detach = [&](int f) {
    for (int k = 0; k < 3; ++k) {
      auto& list = faces[std::minmax(m.tri[f][k], m.tri[f][(k + 1) % 3])];
      list.erase(std::find(list.begin(), list.end(), f));
    }
  };
  for (int f = 0; f < int(m.tri.size()); ++f) attach(f);
  // Longest first; ties broken by the vertex indices, so the result does not depend on the map's layout.
  std::priority_queue<std::tuple<double, int, int>> queue;
  auto push = [&](int a, int b) {
    const auto [lo, hi] = std::minmax(a, b);
    const double length = (m.x[lo] - m.x[hi]).norm();
    if (length > max_edge) queue.emplace(length, lo, hi);
  };
  for (const auto& [e, list] : faces) push(e.first, e.second);
  while (!queue.empty()) {
    const auto [length, a, b] = queue.top();
    queue.pop();
    const auto it = faces.find({a, b});
    if (it == faces.end() || it->second.empty()) continue;  // already split
    const int mid = int(m.x.size());
    m.x.push_back(0.5 * (m.x[a] + m.x[b]));
    const std::vector<int> sharing = it->second;
    for (int f : sharing) {
      detach(f);
      const std::array<int, 3> t = m.tri[f];
      int k = 0;  // the corner where the edge starts, in the triangle's own order
      while (!((t[k] == a && t[(k + 1) % 3] == b) || (t[k] == b && t[(k + 1) % 3] == a))) ++k;
      const int p = t[k], q = t[(k + 1) % 3], r = t[(k + 2) % 3];
      m.tri[f] = {p, mid, r};
      m.tri.push_back({mid, q, r});
      attach(f);
      attach(int(m.tri.size()) - 1);
      push(p, mid);
      push(mid, q);
      push(mid, r);
    }
    faces.erase({a, b});
  }
  return m;
}

double area(const V3& a, const V3& b, const V3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

// Area-weighted vertex normals, normalised.
std::vector<V3> vertexNormals(const std::vector<V3>& x, const std::vector<std::array<int, 3>>& tri) {
  std::vector<V3> n(x.size(), V3::Zero());
  for (const auto& t : tri) {
    const V3 twice_area_normal = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
    for (int k : t) n[k] += twice_area_normal;
  }
  for (V3& v : n)
    if (v.norm() > 0) v.normalize();
  return n;
}

// World point of a frame (position p, row-major rotation r whose columns are the frame's axes).
V3 toWorld(const double* p, const double* r, const V3& local) {
  const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> rot(r);
  return Eigen::Map<const V3>(p) + rot * local;
}

V3 toLocal(const double* p, const double* r, const V3& world) {
  const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> rot(r);
  return rot.transpose() * (world - Eigen::Map<const V3>(p));
}

}  // namespace

FleshMesh buildFleshMesh(const rigid::RigidModel& model, const FleshParams& params) {
  if (const std::string why = params.validate(); !why.empty()) throw std::invalid_argument(why);
  rigid::RigidData reference(model);
  reference.reset();
  reference.kinematics();

  std::vector<V3> rest, anchor;
  std::vector<double> mass;
  FleshMesh out;
  const double t = params.thickness_m;
  for (const rigid::GeomSurface& surface : rigid::geomSurfaces(model, params.slices)) {
    if (surface.body == 0) continue;
    Indexed m = weld(surface.triangles);
    // The flesh's edges are longer than the geom's by up to (r + t) / r: refine the geom's surface to
    // shorter edges until the flesh's are short enough.
    for (double limit = params.max_edge_m; params.max_edge_m > 0 && longestOffsetEdge(m, t) > params.max_edge_m;
         limit *= 0.9) {
      m = bisectLongEdges(std::move(m), limit);
      // A flesh far thicker than its geom's curvature allows needs ever shorter edges: refuse it before it
      // fills the memory.
      if (m.x.size() > kMaxVerticesPerGeom)
        throw std::invalid_argument("flesh: geom " + std::to_string(surface.geom) + " would need more than " +
                                    std::to_string(kMaxVerticesPerGeom) + " vertices for edges of at most " +
                                    std::to_string(params.max_edge_m) + " m under " + std::to_string(t) +
                                    " m of flesh: a thinner flesh or longer edges (a coarser fluid grid)");
    }

    // Stage: the geom's surface in the world at the reference configuration, and the flesh's.
    std::vector<V3> inner(m.x.size()), outer(m.x.size()), middle(m.x.size());
    for (size_t i = 0; i < m.x.size(); ++i)
      inner[i] = toWorld(reference.geomPosition(surface.geom), reference.geomRotation(surface.geom), m.x[i]);
    const std::vector<V3> normal = vertexNormals(inner, m.tri);
    for (size_t i = 0; i < m.x.size(); ++i) {
      outer[i] = inner[i] + t * normal[i];
      middle[i] = inner[i] + 0.5 * t * normal[i];
    }

    // Stage: masses from the shell's prisms (Simpson's rule in the offset).
    std::vector<double> m_geom(m.x.size(), 0.0);
    for (const auto& f : m.tri) {
      const double volume = t / 6 *
                            (area(inner[f[0]], inner[f[1]], inner[f[2]]) + 4 * area(middle[f[0]], middle[f[1]], middle[f[2]]) +
                             area(outer[f[0]], outer[f[1]], outer[f[2]]));
      for (int k : f) m_geom[k] += params.density_kg_per_m3 * volume / 3;
    }

    // Stage: append, bound to the geom's body at the vertex's reference position.
    const int first = int(rest.size());
    for (size_t i = 0; i < m.x.size(); ++i) {
      rest.push_back(outer[i]);
      anchor.push_back(toLocal(reference.bodyPosition(surface.body), reference.bodyRotation(surface.body), outer[i]));
      mass.push_back(m_geom[i]);
      out.body.push_back(surface.body);
      out.geom.push_back(surface.geom);
    }
    for (const auto& f : m.tri) out.triangles.push_back({first + f[0], first + f[1], first + f[2]});
  }
  if (rest.empty())
    throw std::invalid_argument("flesh: model " + model.path() + " has no geom with a volume on a moving body to wrap");
  for (double mi : mass)
    if (!(mi > 0)) throw std::invalid_argument("flesh: a vertex without mass (a geom's surface with a loose vertex)");

  const int n = int(rest.size());
  out.rest_m.resize(3, n);
  out.anchor_in_body_m.resize(3, n);
  out.mass_kg.resize(n);
  for (int i = 0; i < n; ++i) {
    out.rest_m.col(i) = rest[i];
    out.anchor_in_body_m.col(i) = anchor[i];
    out.mass_kg[i] = mass[i];
  }

  // Stage: edges, each once, with the rest area of the triangles that share it.
  std::map<std::pair<int, int>, double> edge_area;
  for (const auto& f : out.triangles) {
    const double a = area(rest[f[0]], rest[f[1]], rest[f[2]]);
    for (int k = 0; k < 3; ++k) edge_area[std::minmax(f[k], f[(k + 1) % 3])] += a;
  }
  for (const auto& [e, a] : edge_area) {
    out.edges.push_back({e.first, e.second});
    out.edge_adjacent_area_m2.push_back(a);
  }
  return out;
}

void vertexAreas(const FleshMesh& mesh, const Eigen::Matrix3Xd& x_m, Eigen::VectorXd& area_m2) {
  area_m2.setZero(x_m.cols());
  for (const auto& f : mesh.triangles) {
    const double a = area(x_m.col(f[0]), x_m.col(f[1]), x_m.col(f[2])) / 3;
    for (int k : f) area_m2[k] += a;
  }
}

}  // namespace creaturelab::flesh
