#pragma once
// POV-Ray 3.7 scene text for the paper's figures (Rudolf & Mould 2009 Figs. 7, 9, 10), written from
// the meshes; the caller writes the files and runs povray headless (runner/render_run.cpp). Surfaces
// are Lambertian (§4: "rendered with a simple Lambertian surface lighting model"): diffuse only, no
// highlights. POV-Ray is left-handed: a point (x, y, z) of the render frame is <x, y, −z> there.
#include <string>
#include <utility>
#include <vector>

#include "render/slice_model2.hpp"
#include "render/triangle_mesh.hpp"

namespace creaturelab::render {

/// An include file declaring `name` as the mesh (mesh2 with per-vertex normals).
std::string povMeshInclude(const TriangleMesh& mesh, const std::string& name);

struct Bounds {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void add(Vec3 p);
  Vec3 centre() const { return 0.5 * (lo + hi); }
};
Bounds boundsOf(const TriangleMesh& mesh);

struct PovView {
  int width_px = 1600, height_px = 900;
  double elevation_deg = 18;  // camera above the horizontal
  double azimuth_deg = 0;     // about the vertical, 0 = looking at the slice plane's front
  double margin = 0.08;       // blank border, as a fraction of the framed size
};

/// A mesh declared in `include_file` as `name`, moved by `offset` (render frame, m), with a caption.
struct PovPlacement {
  std::string include_file, name, caption;
  Bounds bounds;  // of the mesh before the offset
  Vec3 offset;
};

/// Meshes side by side on white, lit from above left, framed by an orthographic camera.
std::string povGalleryScene(const std::vector<PovPlacement>& items, const PovView& view, const std::string& title);

/// A figure: its scene and the mesh include files the scene reads, each as (file name, text).
struct PovFigure {
  std::string name;  // file stem: NAME.pov, rendered to NAME.png
  int width_px = 0, height_px = 0;
  std::string scene;
  std::vector<std::pair<std::string, std::string>> includes;
};

/// A mesh in the sea, as one self-contained scene: a perspective camera looking at `centre_m` from
/// above and to one side (at centre + (0.2, 1.0, −0.55) × size_m), two lights, a sea-blue background
/// and a sandy checker floor 0.4 × size_m below the centre; the mesh inline as a mesh2 with normals.
/// Shaded for a look, not a paper's figure (the fish's skin frames, Tu 1996).
std::string povSeaScene(const TriangleMesh& mesh, Vec3 centre_m, double size_m, const std::string& comment);

/// Fig. 7: the 2-D slice (markers, generated exumbrellar points, resampled outline) in its plane,
/// with the pairs of the listed rings, each pair's axis and its disc.
std::string povSliceDiscsScene(const Slice2& slice, const std::vector<int>& rings, const PovView& view,
                               const std::string& title);

}  // namespace creaturelab::render
