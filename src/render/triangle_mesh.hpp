#pragma once
// A triangle mesh with per-vertex normals, and the checks a closed surface must pass (render/,
// Rudolf & Mould 2009 §3.5: the 3-D jellyfish is a closed, consistently oriented surface).
// Coordinates are metres, right-handed, y up (the slice's axis; glTF's convention too).
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace creaturelab::render {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }

/// What a vertex belongs to (stored per vertex as /render/part).
enum class Part : std::int8_t { exumbrella = 0, subumbrella = 1, tentacle = 2 };

struct TriangleMesh {
  std::vector<Vec3> positions;  // m
  std::vector<Vec3> normals;    // unit, outward
  std::vector<std::array<std::int32_t, 3>> triangles;  // counter-clockwise seen from outside
  std::vector<Part> parts;      // one per vertex
};

/// Area-weighted vertex normals of the triangles, normalised (a vertex without area gets 0).
void computeNormals(TriangleMesh& mesh);

/// Volume enclosed, by the divergence theorem: Σ (a · (b × c)) / 6. Positive when the mesh is
/// closed and its triangles are counter-clockwise seen from outside.
double signedVolume(const TriangleMesh& mesh);

/// V − E + F (2 for each closed component of genus 0).
long eulerCharacteristic(const TriangleMesh& mesh);

/// "" when every edge is used by exactly two triangles, once in each direction (closed, manifold
/// along edges and consistently oriented) and no triangle repeats a vertex; else what is wrong.
std::string checkClosedOriented(const TriangleMesh& mesh);

/// Connected components through shared edges.
int componentCount(const TriangleMesh& mesh);

}  // namespace creaturelab::render
