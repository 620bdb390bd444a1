#include "fish/nurbs.hpp"

#include <algorithm>

namespace creaturelab::fish {

std::vector<double> clampedUniformKnots(int count, int degree) {
  std::vector<double> k(count + degree + 1);
  const int interior = count - degree - 1;
  for (int i = 0; i <= degree; ++i) k[i] = 0.0, k[count + i] = 1.0;
  for (int i = 1; i <= interior; ++i) k[degree + i] = double(i) / double(interior + 1);
  return k;
}

std::string validateNurbs(int count, int degree, const std::vector<double>& knots) {
  if (degree < 1 || degree > 15) return "degree " + std::to_string(degree) + " must be in [1, 15]";
  if (degree >= count)
    return "degree " + std::to_string(degree) + " needs more than " + std::to_string(degree) + " control points (has " +
           std::to_string(count) + ")";
  if (int(knots.size()) != count + degree + 1) return "knot vector must have count + degree + 1 entries";
  for (size_t i = 1; i < knots.size(); ++i)
    if (knots[i] < knots[i - 1]) return "knot vector must not decrease";
  return "";
}

int findSpan(int count, int degree, double u, const std::vector<double>& k) {
  const int n = count - 1;
  if (u >= k[n + 1]) return n;
  if (u <= k[degree]) return degree;
  int lo = degree, hi = n + 1, mid = (lo + hi) / 2;
  while (u < k[mid] || u >= k[mid + 1]) {
    if (u < k[mid]) hi = mid;
    else lo = mid;
    mid = (lo + hi) / 2;
  }
  return mid;
}

void basisFunctions(int span, double u, int p, const std::vector<double>& k, double* n) {
  double left[16], right[16];
  n[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - k[span + 1 - j];
    right[j] = k[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = n[r] / (right[r + 1] + left[j - r]);
      n[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    n[j] = saved;
  }
}

Eigen::Vector3d NurbsCurve::point(double u) const {
  const int count = int(control.size());
  const int span = findSpan(count, degree, u, knots);
  double n[16];
  basisFunctions(span, u, degree, knots, n);
  Eigen::Vector4d h = Eigen::Vector4d::Zero();
  for (int j = 0; j <= degree; ++j) h += n[j] * control[span - degree + j];
  return h.head<3>() / h[3];
}

Eigen::Vector3d NurbsSurface::point(double u, double v) const {
  const int su = findSpan(count_u, degree_u, u, knots_u), sv = findSpan(count_v, degree_v, v, knots_v);
  double nu[16], nv[16];
  basisFunctions(su, u, degree_u, knots_u, nu);
  basisFunctions(sv, v, degree_v, knots_v, nv);
  Eigen::Vector4d h = Eigen::Vector4d::Zero();
  for (int a = 0; a <= degree_u; ++a) {
    Eigen::Vector4d row = Eigen::Vector4d::Zero();
    for (int b = 0; b <= degree_v; ++b) row += nv[b] * at(su - degree_u + a, sv - degree_v + b);
    h += nu[a] * row;
  }
  return h.head<3>() / h[3];
}

SampledBasis sampleBasis(int count, int degree, const std::vector<double>& knots, int samples) {
  SampledBasis b;
  b.degree = degree;
  b.span.resize(samples);
  b.n.resize(size_t(samples) * (degree + 1));
  for (int i = 0; i < samples; ++i) {
    const double u = samples > 1 ? double(i) / double(samples - 1) : 0.0;
    b.span[i] = findSpan(count, degree, u, knots);
    basisFunctions(b.span[i], u, degree, knots, &b.n[size_t(i) * (degree + 1)]);
  }
  return b;
}

void evaluateGrid(const NurbsSurface& s, const SampledBasis& bu, const SampledBasis& bv,
                  std::vector<Eigen::Vector3d>& out, std::vector<Eigen::Vector4d>& column) {
  const int nu = int(bu.span.size()), nv = int(bv.span.size()), pu = bu.degree, pv = bv.degree;
  out.resize(size_t(nu) * nv);
  column.resize(s.count_u);
  for (int iv = 0; iv < nv; ++iv) {
    // pass 1: every control row at this v
    const double* wv = &bv.n[size_t(iv) * (pv + 1)];
    const int sv = bv.span[iv] - pv;
    for (int a = 0; a < s.count_u; ++a) {
      Eigen::Vector4d h = Eigen::Vector4d::Zero();
      for (int b = 0; b <= pv; ++b) h += wv[b] * s.at(a, sv + b);
      column[a] = h;
    }
    // pass 2: along u
    for (int iu = 0; iu < nu; ++iu) {
      const double* wu = &bu.n[size_t(iu) * (pu + 1)];
      const int su = bu.span[iu] - pu;
      Eigen::Vector4d h = Eigen::Vector4d::Zero();
      for (int a = 0; a <= pu; ++a) h += wu[a] * column[su + a];
      out[size_t(iu) * nv + iv] = h.head<3>() / h[3];
    }
  }
}

}  // namespace creaturelab::fish
