#include "render/triangle_mesh.hpp"

#include <algorithm>
#include <numeric>

namespace creaturelab::render {
namespace {

std::uint64_t edgeKey(std::int32_t a, std::int32_t b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }

// Every directed edge (a -> b) of every triangle, sorted.
std::vector<std::uint64_t> directedEdges(const TriangleMesh& mesh) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.push_back(edgeKey(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace

void computeNormals(TriangleMesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), Vec3{});
  const Vec3* p = mesh.positions.data();
  Vec3* n = mesh.normals.data();
  for (const auto& t : mesh.triangles) {
    // |(b - a) × (c - a)| is twice the area: the sum weights each face by its area.
    const Vec3 a = p[t[0]], face = cross(p[t[1]] - a, p[t[2]] - a);
    for (int k = 0; k < 3; ++k) n[t[k]] = n[t[k]] + face;
  }
  for (Vec3& v : mesh.normals) {
    const double length = norm(v);
    v = length > 0 ? (1.0 / length) * v : Vec3{};
  }
}

double signedVolume(const TriangleMesh& mesh) {
  double six_volume = 0;
  for (const auto& t : mesh.triangles)
    six_volume += dot(mesh.positions[t[0]], cross(mesh.positions[t[1]], mesh.positions[t[2]]));
  return six_volume / 6.0;
}

long eulerCharacteristic(const TriangleMesh& mesh) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = t[k], b = t[(k + 1) % 3];
      edges.push_back(edgeKey(std::min(a, b), std::max(a, b)));
    }
  std::sort(edges.begin(), edges.end());
  const long unique_edges = long(std::unique(edges.begin(), edges.end()) - edges.begin());
  return long(mesh.positions.size()) - unique_edges + long(mesh.triangles.size());
}

std::string checkClosedOriented(const TriangleMesh& mesh) {
  const long n = long(mesh.positions.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || t[k] >= n) return "triangle " + std::to_string(f) + " names a vertex outside the mesh";
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return "triangle " + std::to_string(f) + " repeats a vertex";
  }
  const std::vector<std::uint64_t> edges = directedEdges(mesh);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const auto a = std::int32_t(edges[k] >> 32), b = std::int32_t(edges[k] & 0xffffffffu);
    if (k + 1 < edges.size() && edges[k + 1] == edges[k])
      return "edge " + std::to_string(a) + "-" + std::to_string(b) + " is used twice in the same direction";
    if (!std::binary_search(edges.begin(), edges.end(), edgeKey(b, a)))
      return "edge " + std::to_string(a) + "-" + std::to_string(b) + " has no opposite (a hole)";
  }
  return "";
}

int componentCount(const TriangleMesh& mesh) {
  std::vector<std::int32_t> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](std::int32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<char> used(mesh.positions.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = 1;
      parent[find(t[k])] = find(t[(k + 1) % 3]);
    }
  int count = 0;
  for (std::size_t v = 0; v < parent.size(); ++v) count += used[v] && find(std::int32_t(v)) == std::int32_t(v);
  return count;
}

}  // namespace creaturelab::render
