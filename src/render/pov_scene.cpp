#include "render/pov_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace creaturelab::render {
namespace {

// The render frame is right-handed, POV-Ray's left-handed: z changes sign.
Vec3 pov(Vec3 p) { return {p.x, p.y, -p.z}; }
Vec3 pov2(const Eigen::Vector2d& p) { return {p.x(), p.y(), 0.0}; }

std::string vec(Vec3 p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "<%.7g, %.7g, %.7g>", p.x, p.y, p.z);
  return buf;
}

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", x);
  return buf;
}

Vec3 unit(Vec3 v) { return (1.0 / norm(v)) * v; }

// Lambertian lighting (§4: "a simple Lambertian surface lighting model"), a white background and an orthographic camera that frames `points`
// (POV frame) seen from the view's elevation and azimuth.
std::string stage(const std::vector<Vec3>& points, const PovView& view, const std::string& title) {
  Bounds b;
  for (const Vec3& p : points) b.add(p);
  const Vec3 c = b.centre();
  const double el = view.elevation_deg * M_PI / 180, az = view.azimuth_deg * M_PI / 180;
  const Vec3 to_camera{std::sin(az) * std::cos(el), std::sin(el), -std::cos(az) * std::cos(el)};
  const Vec3 forward = -1.0 * to_camera;
  const Vec3 right = unit(Vec3{forward.z, 0, -forward.x});  // y × forward (POV's right for this view)
  const Vec3 up = cross(forward, right);
  double w = 0, h = 0;
  for (const Vec3& p : points) {
    w = std::max(w, 2 * std::abs(dot(p - c, right)));
    h = std::max(h, 2 * std::abs(dot(p - c, up)));
  }
  w *= 1 + 2 * view.margin;
  h *= 1 + 2 * view.margin;
  const double aspect = double(view.width_px) / view.height_px;
  if (w / h < aspect) w = h * aspect;
  else h = w / aspect;
  const double far = 10 * std::max(w, h);
  const Vec3 key = c + far * unit(Vec3{-0.6, 1.0, -0.9}), fill = c + far * unit(Vec3{0.9, 0.2, -0.7});
  std::string s = "// " + title + "\n// creaturelab render; POV-Ray 3.7, e.g. povray +I<this> +O<png> +W" +
                  std::to_string(view.width_px) + " +H" + std::to_string(view.height_px) + " -D +A0.2\n";
  s += "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\nbackground { color rgb 1 }\n";
  s += "camera { orthographic location " + vec(c + far * to_camera) + " look_at " + vec(c) + " right x*" + num(w) +
       " up y*" + num(h) + " }\n";
  // Shadowless: pure n · l shading, as the paper's; shadows of smooth-normal triangles would also
  // show the mesh's facets at grazing light (POV-Ray's "terminator" artefact).
  s += "light_source { " + vec(key) + " color rgb 1.0 shadowless }\n";
  s += "light_source { " + vec(fill) + " color rgb 0.35 shadowless }\n";
  s += "#declare Lambert = finish { ambient 0.08 diffuse 0.92 specular 0 phong 0 }\n";
  s += "#declare Jelly = texture { pigment { color rgb <0.80, 0.85, 0.95> } finish { Lambert } }\n";
  return s;
}

void corners(const Bounds& b, Vec3 offset, std::vector<Vec3>& out) {
  for (int k = 0; k < 8; ++k)
    out.push_back(pov(offset + Vec3{k & 1 ? b.hi.x : b.lo.x, k & 2 ? b.hi.y : b.lo.y, k & 4 ? b.hi.z : b.lo.z}));
}

std::string cylinder(Vec3 a, Vec3 b, double r, const std::string& texture) {
  if (norm(a - b) <= 0) return "";
  return "cylinder { " + vec(a) + ", " + vec(b) + ", " + num(r) + " " + texture + " }\n";
}

}  // namespace

void Bounds::add(Vec3 p) {
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

Bounds boundsOf(const TriangleMesh& mesh) {
  Bounds b;
  for (const Vec3& p : mesh.positions) b.add(p);
  return b;
}

std::string povMeshInclude(const TriangleMesh& mesh, const std::string& name) {
  std::string s = "#declare " + name + " = mesh2 {\n  vertex_vectors { " + std::to_string(mesh.positions.size());
  s.reserve(80 * (2 * mesh.positions.size() + mesh.triangles.size()));
  char buf[112];
  for (const Vec3& p : mesh.positions) {
    std::snprintf(buf, sizeof buf, ",\n    <%.8g, %.8g, %.8g>", p.x, p.y, -p.z);
    s += buf;
  }
  s += " }\n  normal_vectors { " + std::to_string(mesh.normals.size());
  for (const Vec3& n : mesh.normals) {
    std::snprintf(buf, sizeof buf, ",\n    <%.6f, %.6f, %.6f>", n.x, n.y, -n.z);
    s += buf;
  }
  s += " }\n  face_indices { " + std::to_string(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    std::snprintf(buf, sizeof buf, ",\n    <%d, %d, %d>", t[0], t[1], t[2]);
    s += buf;
  }
  return s + " }\n}\n";
}

std::string povGalleryScene(const std::vector<PovPlacement>& items, const PovView& view, const std::string& title) {
  std::vector<Vec3> frame;
  std::string objects;
  double widest = 0;
  for (const auto& item : items) widest = std::max(widest, item.bounds.hi.x - item.bounds.lo.x);
  for (const auto& item : items) {
    corners(item.bounds, item.offset, frame);
    objects += "#include \"" + item.include_file + "\"\nobject { " + item.name + " texture { Jelly } translate " +
               vec(pov(item.offset)) + " }\n";
    if (item.caption.empty()) continue;
    // Times Roman, about half an em per character: centred under the item.
    const double size = 0.1 * widest;
    const Vec3 at{item.offset.x + item.bounds.centre().x - 0.25 * size * double(item.caption.size()),
                  item.offset.y + item.bounds.lo.y - 1.3 * size, item.offset.z + item.bounds.hi.z};
    objects += "text { ttf \"timrom.ttf\" \"" + item.caption + "\" 0.02, 0 pigment { color rgb 0.1 } finish { ambient 1 "
               "diffuse 0 } no_shadow scale " + num(size) + " translate " + vec(pov(at)) + " }\n";
    frame.push_back(pov(at));
    frame.push_back(pov(at + Vec3{0.5 * size * double(item.caption.size()), size, 0}));
  }
  return stage(frame, view, title) + objects;
}

std::string povSliceDiscsScene(const Slice2& slice, const std::vector<int>& rings, const PovView& view,
                               const std::string& title) {
  Bounds b;
  for (const auto* curve : {&slice.sub_markers, &slice.exum_markers})
    for (const auto& p : *curve) b.add(pov2(p));
  const double size = std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
  const double r_point = 0.010 * size, r_line = 0.0035 * size;
  const std::string ink = "texture { pigment { color rgb 0.15 } finish { Lambert } }";
  const std::string flesh = "texture { pigment { color rgb <0.45, 0.55, 0.75> } finish { Lambert } }";
  const std::string pair = "texture { pigment { color rgb <0.80, 0.15, 0.10> } finish { Lambert } }";
  std::vector<Vec3> frame;
  std::string objects;
  // The resampled outline with its thickness: subumbrella, margins, exumbrella.
  const int n = int(slice.sub_left.size());
  std::vector<Vec3> outline;
  for (int i = 0; i < n; ++i) outline.push_back(pov2(slice.sub_left[i]));
  for (int i = n - 2; i >= 0; --i) outline.push_back(pov2(slice.sub_right[i]));
  for (int i = 0; i < n; ++i) outline.push_back(pov2(slice.exum_right[i]));
  for (int i = n - 2; i >= 0; --i) outline.push_back(pov2(slice.exum_left[i]));
  for (std::size_t k = 0; k < outline.size(); ++k) {
    objects += cylinder(outline[k], outline[(k + 1) % outline.size()], r_line, flesh);
    frame.push_back(outline[k]);
  }
  // The simulation's point masses (the subumbrella) and the exumbrellar points made from them.
  for (const auto& p : slice.sub_markers) objects += "sphere { " + vec(pov2(p)) + ", " + num(r_point) + " " + ink + " }\n";
  for (const auto& p : slice.exum_markers)
    objects += "sphere { " + vec(pov2(p)) + ", " + num(0.7 * r_point) + " " + flesh + " }\n";
  // Each example pair: its points, the chord between them, the axis through the chord's middle
  // at right angles to it (in the slice), and the disc the pair sweeps about that axis.
  for (int i : rings) {
    if (i < 0 || i >= n - 1) continue;
    const Vec3 l = pov2(slice.sub_left[i]), r = pov2(slice.sub_right[i]), c = 0.5 * (l + r);
    const double radius = 0.5 * norm(r - l);
    const Vec3 chord = unit(r - l), axis{-chord.y, chord.x, 0};
    const double phi = std::atan2(-axis.x, axis.y) * 180 / M_PI;  // rotates the torus's +y onto the axis
    objects += "sphere { " + vec(l) + ", " + num(1.5 * r_point) + " " + pair + " }\n";
    objects += "sphere { " + vec(r) + ", " + num(1.5 * r_point) + " " + pair + " }\n";
    objects += cylinder(l, r, 0.6 * r_line, pair);
    objects += cylinder(c - 0.12 * size * axis, c + 0.12 * size * axis, 0.5 * r_line, ink);
    objects += "disc { " + vec(c) + ", " + vec(axis) + ", " + num(radius) +
               " texture { pigment { color rgbf <0.55, 0.75, 1.0, 0.65> } finish { Lambert } } }\n";
    objects += "torus { " + num(radius) + ", " + num(0.6 * r_line) + " " + pair + " rotate <0, 0, " + num(phi) +
               "> translate " + vec(c) + " }\n";
    for (double z : {-radius, radius}) frame.push_back(c + Vec3{0, 0, z});
  }
  return stage(frame, view, title) + objects;
}

std::string povSeaScene(const TriangleMesh& mesh, Vec3 c, double L, const std::string& comment) {
  std::ostringstream out;
  out.precision(9);
  const auto vec9 = [](Vec3 v) {
    const Vec3 p = pov(v);
    std::ostringstream s;
    s.precision(9);
    s << '<' << p.x << ", " << p.y << ", " << p.z << '>';
    return s.str();
  };
  out << "// " << comment << "\n#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      << "background { rgb <0.05, 0.22, 0.35> }\n"
      << "camera { perspective location " << vec9(c + Vec3{0.2 * L, 1.0 * L, -0.55 * L}) << " look_at " << vec9(c)
      << " angle 50 right x*image_width/image_height }\n"
      << "light_source { " << vec9(c + Vec3{0.5 * L, 3 * L, -1.5 * L}) << " color rgb <1, 1, 0.95> }\n"
      << "light_source { " << vec9(c + Vec3{-2 * L, 1 * L, 1 * L}) << " color rgb <0.3, 0.35, 0.45> shadowless }\n"
      << "plane { y, " << c.y - 0.4 * L << " pigment { checker rgb <0.75, 0.7, 0.55>, rgb <0.65, 0.6, 0.45> scale "
      << 0.25 * L << " } finish { ambient 0.15 } }\n";
  out << "mesh2 {\n  vertex_vectors { " << mesh.positions.size();
  for (const Vec3& p : mesh.positions) out << ",\n    " << vec9(p);
  out << "\n  }\n  normal_vectors { " << mesh.normals.size();
  for (const Vec3& n : mesh.normals) out << ",\n    " << vec9(n);
  out << "\n  }\n  face_indices { " << mesh.triangles.size();
  for (const auto& t : mesh.triangles) out << ",\n    <" << t[0] << ", " << t[1] << ", " << t[2] << '>';
  out << "\n  }\n  pigment { gradient y color_map { [0 rgb <0.85, 0.82, 0.7>] [1 rgb <0.25, 0.45, 0.6>] } scale "
      << 0.5 * L << " translate <0, " << c.y - 0.25 * L << ", 0> }\n"
      << "  finish { ambient 0.2 diffuse 0.7 specular 0.4 roughness 0.02 }\n}\n";
  return out.str();
}

}  // namespace creaturelab::render
