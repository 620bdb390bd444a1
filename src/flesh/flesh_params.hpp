#pragma once
// Parameters of the flesh of Lentine et al. 2010 §7.1-7.2: "a deformable mesh that is bound to the
// rigid body skeleton, using fully implicit springs ... for stability". The paper gives no thickness,
// density, stiffness or resolution: the defaults below are chosen (each says why) and configurable.
// Plain struct with in-class defaults; validate() says in words what is wrong.
#include <string>

namespace creaturelab::flesh {

struct FleshParams {
  // Geometry (flesh_mesh.hpp): every geom's surface pushed outward along its vertex normals.
  double thickness_m = 0.01;  // flesh layer over the skeleton's geoms; chosen: 40% of the swimmer's leg radius
  int slices = 16;            // segments around each round geom (rigid::geomSurfaces), >= 3
  // Longest edges bisected (flesh_mesh.cpp) until no edge of the flesh is longer; 0 keeps the
  // tessellation as it is. Lets a box or a long capsule reach the fluid's marker spacing.
  double max_edge_m = 0.0;

  // Mass: density times the shell's volume (flesh_mesh.hpp). Skeletal muscle, 1050 kg/m^3
  // (ICRU Report 44, 1989).
  double density_kg_per_m3 = 1050.0;

  // Stretch springs on the mesh edges, from a membrane of Young's modulus E and the flesh's
  // thickness t (Van Gelder 1998, "Approximate simulation of elastic membranes by triangulated spring
  // meshes", J. Graphics Tools 3(2)): k_e = E t sum_{T adjacent to e} area(T) / |e|^2. Chosen: 10 kPa,
  // within the 1-100 kPa of soft tissues (Fung, "Biomechanics: mechanical properties of living
  // tissues", 1993).
  double youngs_modulus_pa = 1.0e4;
  // Edge damping as a ratio of the critical damping of the edge's two masses:
  // c_e = 2 zeta sqrt(k_e m_a m_b / (m_a + m_b)). Chosen: lightly damped.
  double stretch_damping_ratio = 0.1;

  // Binding: a zero-length spring from each vertex to its anchor, a point fixed in its body's frame,
  // given as the frequency of a vertex on its binding alone (Box2D's convention: hertz and a damping
  // ratio, so the binding does not depend on the mesh's resolution): k_i = m_i (2 pi f)^2,
  // c_i = 2 zeta m_i 2 pi f. Chosen: 10 Hz, faster than the flyer's and swimmer's strokes (about
  // 1 Hz) so the flesh follows them, slow enough to sway in the flow; damped at half the critical.
  double binding_hz = 10.0;
  double binding_damping_ratio = 0.5;

  // true: the skeleton's velocity change under the binding's reactions is solved with the flesh's
  // (flesh.hpp), stable for any binding stiffness and any flesh-to-bone mass ratio. false: the bodies
  // get the reactions explicitly (one unknown fewer per DOF; a free 2 kg sphere with 1.4 kg of flesh
  // bound at 100 Hz blows up at 10 ms steps).
  bool implicit_skeleton = true;

  // Backward Euler's linear solve (conjugate gradients, Jacobi preconditioner): stops when
  // |A dv - b| / |b| <= cg_tolerance, or after cg_max_iterations.
  double cg_tolerance = 1e-10;
  int cg_max_iterations = 1000;

  // "" when usable; otherwise a sentence naming the first bad field, its value and what it must be.
  std::string validate() const;

  // The parameters a kind offers, each named flesh_<field> (kinds/describe.hpp's visitor). max_edge_m is
  // left out: a fluid coupling sets it from the markers' spacing.
  template <class V>
  void describe(V& v) {
    v.real("flesh_thickness_m", thickness_m, "m", 1e-6, 10, "flesh layer over the skeleton's geoms (the paper gives none)");
    v.integer("flesh_slices", slices, 3, 1024, "segments around each round geom of the flesh");
    v.real("flesh_density_kg_per_m3", density_kg_per_m3, "kg/m^3", 1e-3, 1e5, "flesh density (skeletal muscle: 1050)");
    v.real("flesh_youngs_modulus_pa", youngs_modulus_pa, "Pa", 1e-3, 1e12,
           "stretch springs' membrane modulus (Van Gelder 1998); soft tissue 1-100 kPa");
    v.real("flesh_stretch_damping_ratio", stretch_damping_ratio, "", 0, 100, "edge damping, 1 = critical");
    v.real("flesh_binding_hz", binding_hz, "Hz", 1e-6, 1e6, "frequency of a vertex on its binding spring to the skeleton");
    v.real("flesh_binding_damping_ratio", binding_damping_ratio, "", 0, 100, "binding damping, 1 = critical");
    v.real("flesh_cg_tolerance", cg_tolerance, "", 1e-16, 0.5, "backward Euler's linear solve: relative residual");
  }
};

}  // namespace creaturelab::flesh
