#pragma once
// A short NURBS evaluator (our own, not Eigen's unsupported Splines module: that module has no
// rational surfaces and its knot utilities allocate per call; ours precomputes the basis of a
// sampling grid once). Algorithms A2.1 (span) and A2.2 (basis functions) of Piegl & Tiller,
// "The NURBS Book" (2nd ed., 1997); rational points by evaluating in homogeneous coordinates
// (w P, w) and dividing (ibid. §4.2, Eq. 4.2). Tested against the exact rational quadratic circle.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace creaturelab::fish {

// Clamped (open) uniform knot vector for `count` control points of degree p:
// p + 1 zeros, count - p - 1 interior knots evenly spaced, p + 1 ones. The surface then passes
// through its corner control points and its boundary curves depend only on the boundary rows.
std::vector<double> clampedUniformKnots(int count, int degree);

// "" or what is wrong: degree >= 1, degree < count ("a NURBS degree above its control-point count"),
// knots non-decreasing and count + degree + 1 long.
std::string validateNurbs(int count, int degree, const std::vector<double>& knots);

// A2.1: the knot span index i with knots[i] <= u < knots[i + 1] (the last span for u = the end).
int findSpan(int count, int degree, double u, const std::vector<double>& knots);
// A2.2: the degree + 1 non-zero basis functions N_{span - degree .. span, degree}(u) into n.
void basisFunctions(int span, double u, int degree, const std::vector<double>& knots, double* n);

// A NURBS curve in homogeneous coordinates (w x, w y, w z, w) — enough for the circle test.
struct NurbsCurve {
  int degree = 2;
  std::vector<double> knots;
  std::vector<Eigen::Vector4d> control;  // homogeneous
  Eigen::Vector3d point(double u) const;
};

// A tensor-product NURBS surface: control points on a (count_u x count_v) grid, row-major in u.
struct NurbsSurface {
  int degree_u = 3, degree_v = 3;
  int count_u = 0, count_v = 0;
  std::vector<double> knots_u, knots_v;
  std::vector<Eigen::Vector4d> control;  // homogeneous (w P, w), index iu * count_v + iv
  Eigen::Vector4d& at(int iu, int iv) { return control[iu * count_v + iv]; }
  const Eigen::Vector4d& at(int iu, int iv) const { return control[iu * count_v + iv]; }
  Eigen::Vector3d point(double u, double v) const;
};

// The basis functions of a surface at the parameters of a sampling grid, computed once: spans and
// (degree + 1) values per sample.
struct SampledBasis {
  int degree = 0;
  std::vector<int> span;
  std::vector<double> n;  // samples x (degree + 1)
};
SampledBasis sampleBasis(int count, int degree, const std::vector<double>& knots, int samples);

// The surface at samples_u x samples_v parameters evenly spaced over [0, 1]^2 (both ends included),
// into out (row-major in u: out[iu * samples_v + iv]); two passes (v, then u) so a point costs
// about (degree_u + 1) rather than (degree_u + 1)(degree_v + 1) multiply-adds.
void evaluateGrid(const NurbsSurface& s, const SampledBasis& bu, const SampledBasis& bv,
                  std::vector<Eigen::Vector3d>& out, std::vector<Eigen::Vector4d>& scratch);

}  // namespace creaturelab::fish
