#pragma once
// The NURBS skin of the fish, bound to the faces of the dynamic model
// (X. Tu, Artificial Animals for Computer Animation, 1996, ch. 7; docs/fish-spec.md §4):
//   set-up, on the undeformed model: each face is the bilinear patch P(s, t) of its four corners,
//   split 4 x 4 into 25 "patch-nodes"; a local frame per face (u = the normal, v = a face edge,
//   w = u x v); for each control point its offset from its patch-node, in that frame;
//   each display step: recompute patch-nodes and frames, control point = patch-node + offset in
//   the new frame.
// Choices (spec §4 [choose]): normal = normalize((c2 - c0) x (c3 - c1)); v = the first non-zero
// edge made orthogonal to u; each control point binds to its nearest patch-node (9 patch-nodes
// around a half body match its 9 control points, but 25 along do not match 21).
//
// The display body is two half surfaces, left and right (spec §4: 9 x 21 control points each),
// from the dorsal midline round one side to the ventral midline, snout to tail; the thesis's
// "order 3 (degree 4)" is ambiguous: we take degree 3 (cubic, order 4) both ways, configurable.
// Clamped knots make the surface pass through its boundary rows: the two halves share their
// midline control points exactly (same patch-node, same offset), so the skin is closed there.
// Dorsal and ventral fins are NURBS surfaces (3 x 5 control points, degree 2 x 3) whose base row
// is the body's midline control points (shared, spec §4). Pectoral fins are left out.
// The control net's shape is ours: elliptical sections through the body's rings, inflated by
// `inflate` (a B-spline surface lies inside its control hull), closing to a point at the snout
// and to the caudal fin's trailing edge at the tail.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fish/fish_model.hpp"
#include "fish/nurbs.hpp"

namespace creaturelab::fish {

constexpr int kSkinAround = 9;  // control points around a half body
constexpr int kSkinAlong = 21;  // along it

struct SkinParams {
  int degree_around = 3;
  int degree_along = 3;
  double inflate = 1.15;  // control-net section / body section
  bool fins = true;
  // Pectoral fins (spec §4: 5-vertex polygons posed in the fish frame): display geometry only. The
  // thesis's text we cite gives them no force, so they neither lift nor brake; their pose is set
  // here, not by a controller. pitch: the fin turned about the fish's lateral axis through its root,
  // leading edge up > 0 (the pose an ascending fish shows), degrees.
  bool pectoral_fins = true;
  double pectoral_pitch_deg = 0.0;

  // For the fish kind (kinds/describe.hpp).
  template <class V>
  void describe(V& v) {
    v.integer("skin_degree_around", degree_around, 1, 15,
              "NURBS degree around the body (9 control points; spec §4 [choose]: cubic)");
    v.integer("skin_degree_along", degree_along, 1, 15, "NURBS degree along the body (21 control points; cubic)");
    v.real("skin_inflate", inflate, "", 1e-3, 100, "control-net section / body section (ours: the surface lies inside its net)");
    v.boolean("skin_fins", fins, "dorsal and ventral fin surfaces sharing the midline control points");
    v.boolean("skin_pectoral_fins", pectoral_fins,
              "pectoral fins (spec §4: 5-vertex polygons posed in the fish frame), display only: no force acts on them");
    v.real("pectoral_pitch_deg", pectoral_pitch_deg, "deg", -90, 90,
           "the pectoral fins' pose: turned about the fish's lateral axis, leading edge up > 0 (display only)");
  }

  // "" or what is wrong, naming the parameter (a degree not below its control-point count, ...).
  std::string validate() const;
};

// A triangle mesh with per-vertex normals. Parts: the body halves first (left, right: each
// samples_around x samples_along vertices, row-major around), then the fins, then the pectoral
// fins (left, right: 5 vertices and 3 triangles each).
struct SkinMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector3d> normals;
  std::vector<std::array<int, 3>> triangles;
  int samples_around = 0, samples_along = 0;
  int body_triangles = 0;  // the first body_triangles triangles are the body (the rest: fins)
};

// Where a control point is bound: face, patch-node (s, t in quarters) and offset in the face frame.
struct SkinBinding {
  int face = 0;
  int s = 0, t = 0;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // (u, v, w) components
};

class FishSkin {
 public:
  // Binds the skin to the undeformed fish (kept by reference: it must outlive the skin). Throws
  // std::invalid_argument on bad parameters.
  FishSkin(const FishModel& fish, SkinParams params);

  // Control points from node positions (homogeneous, weight 1).
  void update(const NodeMatrix& x);
  // Samples the current surfaces into a mesh (update() first).
  void mesh(int samples_around, int samples_along, SkinMesh& out);
  // The pectoral fins' 5 vertices each (left, then right) at node positions x: posed in the fish
  // frame (origin at the fin's root on the lower flank between rings 1 and 2; axes forward, left, up
  // from the nodes), so a rigid motion of the nodes carries them exactly.
  std::array<Eigen::Vector3d, 10> pectoralFins(const NodeMatrix& x) const;

  const std::vector<NurbsSurface>& surfaces() const { return surfaces_; }  // left, right, fins
  const std::vector<SkinBinding>& bindings() const { return bindings_; }   // per control point, surface order
  // The undeformed control points (surface order).
  const std::vector<Eigen::Vector3d>& restControlPoints() const { return rest_control_; }
  // All current control points, surface order.
  std::vector<Eigen::Vector3d> controlPoints() const;

  // Patch-node (s, t in quarters) of a face, and a face's frame (columns u, v, w), at positions x.
  static Eigen::Vector3d patchNode(const NodeMatrix& x, const Face& f, int s, int t);
  static Eigen::Matrix3d faceFrame(const NodeMatrix& x, const Face& f);

 private:
  const FishModel& fish_;
  SkinParams params_;
  std::vector<NurbsSurface> surfaces_;
  std::vector<SkinBinding> bindings_;
  std::vector<Eigen::Vector3d> rest_control_;
  std::array<Eigen::Matrix3d, kFaces> frames_;
  NodeMatrix nodes_;  // the positions of the last update()
  // sampling caches
  int cached_around_ = -1, cached_along_ = -1;
  std::vector<SampledBasis> basis_u_, basis_v_;
  std::vector<Eigen::Vector3d> grid_;
  std::vector<Eigen::Vector4d> scratch_;
};

// Fold-over check of the body part of a mesh.
// outward: a triangle points outward when its normal has a positive component along the outward
//   normal of its station's section, taken as an ellipse of the section's half-extents (the gradient
//   of (y/a)^2 + (z/b)^2: on the thin tail the direction from the centre alone would point along the
//   fin instead of across it). Used on the undeformed skin, where sections are convex.
// folds: neighbouring triangles (sharing an edge of a half's sampling grid) whose normals point
//   more than 90 degrees apart: the mesh folds over there. Used over a swim, where a bent thin tail
//   makes "outward from the section's centre" ill-defined but a fold still shows as a crease.
// Degenerate triangles (area below 1e-12 of the largest: the snout's pole) are skipped.
struct FoldCheck {
  int checked = 0;
  int inward = 0;             // triangles whose normal points into the body (outward test)
  double worst_cosine = 1;    // smallest cos(normal, outward direction)
  int worst_triangle = -1;    // its index
  int creases = 0;            // neighbouring pairs more than 90 degrees apart
  double worst_neighbour_cosine = 1;
};
FoldCheck checkOutward(const SkinMesh& mesh);

// The largest distance between the two body halves where they must meet: their first and last rows
// around (the dorsal and ventral midlines) and their last station (the tail edge). Zero for a closed skin.
double seamGapM(const SkinMesh& mesh);

}  // namespace creaturelab::fish
