#include "render/slice_model2.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace creaturelab::render {
namespace {

using Eigen::Vector2d;

Vector2d marker(const SliceFrame& f, int k) { return {f.markers_xy[2 * k], f.markers_xy[2 * k + 1]}; }

double cross2(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }
double orient(const Vector2d& a, const Vector2d& b, const Vector2d& c) { return cross2(b - a, c - a); }

// Segments p1p2 and q1q2 cross at a point inside both (a proper crossing).
bool crosses(const Vector2d& p1, const Vector2d& p2, const Vector2d& q1, const Vector2d& q2) {
  const double o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2), o3 = orient(q1, q2, p1), o4 = orient(q1, q2, p2);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

std::string at(const SliceFrame& f) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "t = %.6g s: ", f.time_s);
  return buf;
}

}  // namespace

SplineInterpolator::SplineInterpolator(int points) {
  if (points < 2) return;
  const int n = points, degree = std::min(3, n - 1);
  parameters_.resize(n);
  for (int k = 0; k < n; ++k) parameters_[k] = double(k) / double(n - 1);
  Spline2::KnotVectorType parameters = parameters_.array();
  Eigen::KnotAveraging(parameters, degree, knots_);
  // Piegl & Tiller §9.2.1 (as Eigen's SplineFitting::Interpolate): row k holds the basis
  // functions at u_k; the ends interpolate their control points.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int k = 1; k < n - 1; ++k) {
    const Eigen::DenseIndex span = Spline2::Span(parameters[k], degree, knots_);
    a.row(k).segment(span - degree, degree + 1) = Spline2::BasisFunctions(parameters[k], degree, knots_);
  }
  a(0, 0) = 1.0;
  a(n - 1, n - 1) = 1.0;
  collocation_.compute(a);
}

Spline2 SplineInterpolator::fit(const Eigen::Matrix2Xd& pts) const {
  const Eigen::Matrix2Xd controls = collocation_.solve(pts.transpose()).transpose();
  return Spline2(knots_, controls);
}

std::string SliceTopology::validate(int markers) const {
  if (bell_markers < 5 || bell_markers % 2 == 0)
    return "the bell needs an odd number (>= 5) of markers with the apex in the middle, got " +
           std::to_string(bell_markers);
  if (bell_markers > markers) return "the topology names more bell markers than the frames hold";
  for (const auto* chain : {&left_tentacle, &right_tentacle}) {
    if (chain->size() == 1) return "a tentacle needs at least its root and one more marker";
    for (int m : *chain)
      if (m < 0 || m >= markers) return "a tentacle names a marker outside the frames";
  }
  if (left_tentacle.empty() != right_tentacle.empty()) return "tentacles must come in left-right pairs";
  if (!left_tentacle.empty() && (left_tentacle.front() != 0 || right_tentacle.front() != bell_markers - 1))
    return "each tentacle must start at its aperture marker";
  for (std::size_t m = 0; m < muscle_markers.size(); ++m) {
    if (muscle_markers[m] < 0 || muscle_markers[m] > bell_markers / 2) return "a muscle element is outside the bell's half";
    if (m > 0 && muscle_markers[m] <= muscle_markers[m - 1]) return "muscle elements must be listed from the aperture up";
  }
  return "";
}

namespace {

// The chain of markers beyond the bell that starts at `root`, through the springs.
std::vector<int> tentacleChain(int root, int bell_markers, std::span<const std::int64_t> springs, int markers) {
  std::vector<std::vector<int>> next(markers);
  for (std::size_t s = 0; s + 1 < springs.size(); s += 2) {
    const auto a = springs[s], b = springs[s + 1];
    if (a < 0 || b < 0 || a >= markers || b >= markers) continue;
    next[a].push_back(int(b));
    next[b].push_back(int(a));
  }
  std::vector<int> chain{root};
  for (int at = root; at >= 0 && at < markers;) {
    int step = -1;
    for (int n : next[at])
      if (n >= bell_markers && std::find(chain.begin(), chain.end(), n) == chain.end()) step = n;
    if (step < 0) break;
    chain.push_back(step);
    at = step;
  }
  return chain.size() > 1 ? chain : std::vector<int>{};
}

}  // namespace

SliceTopology sliceTopology(int bell_markers, std::span<const std::int64_t> springs,
                            std::span<const std::int64_t> muscles, int markers) {
  SliceTopology t;
  t.bell_markers = bell_markers;
  t.left_tentacle = tentacleChain(0, bell_markers, springs, markers);
  t.right_tentacle = tentacleChain(bell_markers - 1, bell_markers, springs, markers);
  for (std::size_t m = 0; m + 1 < muscles.size(); m += 2) t.muscle_markers.push_back(int(muscles[m]));
  return t;
}

SliceModel2::SliceModel2(const RenderParams& params, SliceTopology topology, int markers)
    : params_(params),
      topology_(std::move(topology)),
      markers_(markers),
      bell_(topology_.bell_markers),
      tentacle_left_(int(topology_.left_tentacle.size())),
      tentacle_right_(int(topology_.right_tentacle.size())) {
  if (std::string e = params_.validate(); !e.empty()) throw std::invalid_argument(e);
  if (std::string e = topology_.validate(markers); !e.empty()) throw std::invalid_argument(e);
}

void SliceModel2::projectExumbrella(const SliceFrame& frame, Eigen::Matrix2Xd& sub, Eigen::Matrix2Xd& exum,
                                    Spline2* spline) const {
  const int n = topology_.bell_markers, apex = n / 2;
  sub.resize(2, n);
  for (int k = 0; k < n; ++k) sub.col(k) = marker(frame, k);
  const Spline2 s = bell_.fit(sub);
  exum.resize(2, n);
  for (int k = 0; k < n; ++k) {
    // The outward normal is the tangent turned left: the markers run left aperture → apex →
    // right aperture, so left of the travel is away from the bell's cavity (§3.4 "backward").
    const Vector2d tangent = s.derivatives(double(k) / double(n - 1), 1).col(1);
    const double length = tangent.norm();
    const Vector2d normal = length > 0 ? Vector2d(-tangent.y() / length, tangent.x() / length) : Vector2d(0, 0);
    const double d = std::abs(double(k - apex)) / double(apex);
    exum.col(k) = sub.col(k) + params_.thickness.at(d) * normal;
  }
  if (spline) *spline = s;
}

std::string SliceModel2::check(const SliceFrame& frame) const {
  if (int(frame.markers_xy.size()) != 2 * markers_)
    return at(frame) + "the frame holds " + std::to_string(frame.markers_xy.size() / 2) + " markers, expected " +
           std::to_string(markers_);
  for (double v : frame.markers_xy)
    if (!std::isfinite(v)) return at(frame) + "a marker's coordinate is not finite";
  const int n = topology_.bell_markers;
  for (int k = 0; k + 1 < n; ++k)
    if (marker(frame, k) == marker(frame, k + 1))
      return at(frame) + "bell markers " + std::to_string(k) + " and " + std::to_string(k + 1) + " coincide";
  for (const auto* chain : {&topology_.left_tentacle, &topology_.right_tentacle})
    for (std::size_t k = 0; k + 1 < chain->size(); ++k)
      if (marker(frame, (*chain)[k]) == marker(frame, (*chain)[k + 1]))
        return at(frame) + "tentacle markers " + std::to_string((*chain)[k]) + " and " +
               std::to_string((*chain)[k + 1]) + " coincide";
  Eigen::Matrix2Xd sub, exum;
  projectExumbrella(frame, sub, exum, nullptr);
  // The closed outline of the slice with its thickness: subumbrella left → right, the right
  // margin, the exumbrella right → left, the left margin.
  std::vector<Vector2d> loop;
  for (int k = 0; k < n; ++k) loop.push_back(sub.col(k));
  for (int k = n - 1; k >= 0; --k) loop.push_back(exum.col(k));
  const int m = int(loop.size());
  for (int a = 0; a < m; ++a)
    for (int b = a + 2; b < m; ++b) {
      if (a == 0 && b == m - 1) continue;  // neighbours across the loop's start
      if (crosses(loop[a], loop[(a + 1) % m], loop[b], loop[(b + 1) % m])) {
        const auto name = [n, m](int e) {
          return e < n - 1 ? "subumbrella segment " + std::to_string(e)
                 : e == n - 1 ? std::string("the right margin")
                 : e == m - 1 ? std::string("the left margin")
                              : "exumbrella segment " + std::to_string(2 * n - 2 - e);
        };
        return at(frame) + "the bell's outline crosses itself (" + name(a) + " and " + name(b) +
               "): a degenerate slice cannot be extrapolated to a closed surface";
      }
    }
  // No orientation check is needed: the exumbrella is generated on the left of the markers' travel,
  // so the flesh is always on the left of "subumbrella forward, exumbrella back", and the disc
  // stitching turns exactly that into outward normals (disc_extrapolation.cpp). A bell upside
  // down or mirrored is a valid, outward surface too; only a crossing breaks it.
  return "";
}

double SliceModel2::ringContraction(double q, std::span<const double> activation) const {
  const auto& at_marker = topology_.muscle_markers;
  if (activation.empty() || at_marker.empty()) return 0.0;
  const auto a = [&](std::size_t m) { return std::clamp(activation[m], 0.0, 1.0); };
  const double apex = 0.5 * (topology_.bell_markers - 1);
  if (q <= at_marker.front()) return a(0);
  for (std::size_t m = 0; m + 1 < at_marker.size(); ++m)
    if (q <= at_marker[m + 1]) {
      const double w = (q - at_marker[m]) / double(at_marker[m + 1] - at_marker[m]);
      return (1 - w) * a(m) + w * a(m + 1);
    }
  // Above the muscle band toward the apex, where no element acts: down to 0 at the apex, whose
  // ring has no circumference to compress.
  const double last = at_marker.back();
  if (last >= apex) return a(at_marker.size() - 1);
  return a(at_marker.size() - 1) * std::max(0.0, (apex - q) / (apex - last));
}

void SliceModel2::build(const SliceFrame& frame, Slice2& out) const {
  const int rings = params_.rings, n = topology_.bell_markers;
  Eigen::Matrix2Xd sub, exum;
  Spline2 sub_spline;
  projectExumbrella(frame, sub, exum, &sub_spline);
  const Spline2 exum_spline = bell_.fit(exum);
  for (auto* v : {&out.sub_left, &out.sub_right, &out.exum_left, &out.exum_right}) v->resize(rings);
  out.latitude.resize(rings);
  out.thickness_m.resize(rings);
  out.contraction.resize(rings);
  if (frame.muscle_activation.size() != topology_.muscle_markers.size() && !frame.muscle_activation.empty())
    throw std::invalid_argument("the frame's muscle activation has " + std::to_string(frame.muscle_activation.size()) +
                                " values for " + std::to_string(topology_.muscle_markers.size()) + " muscle elements");
  for (int i = 0; i < rings; ++i) {
    // Ring i pairs the points at material coordinate s from each aperture (s = 0 the margin,
    // 1 the apex): the render model's "opposing pairs" (§3.5), as the muscle joins marker k to
    // marker N − k.
    const double s = double(i) / double(rings - 1);
    const double u_left = 0.5 * s, u_right = 1.0 - 0.5 * s;
    out.sub_left[i] = sub_spline(u_left);
    out.sub_right[i] = sub_spline(u_right);
    out.exum_left[i] = exum_spline(u_left);
    out.exum_right[i] = exum_spline(u_right);
    out.latitude[i] = 1.0 - s;
    out.thickness_m[i] = params_.thickness.at(1.0 - s);
    out.contraction[i] = ringContraction(u_left * (n - 1), frame.muscle_activation);
  }
  out.sub_markers.resize(n);
  out.exum_markers.resize(n);
  for (int k = 0; k < n; ++k) {
    out.sub_markers[k] = sub.col(k);
    out.exum_markers[k] = exum.col(k);
  }
  const int samples = topology_.left_tentacle.empty() ? 0 : params_.tentacle_rings;
  out.tentacle_left.resize(samples);
  out.tentacle_right.resize(samples);
  if (samples == 0) return;
  const auto sampleChain = [&](const std::vector<int>& chain, const SplineInterpolator& fit,
                               std::vector<Vector2d>& dst) {
    Eigen::Matrix2Xd pts(2, chain.size());
    for (std::size_t k = 0; k < chain.size(); ++k) pts.col(Eigen::Index(k)) = marker(frame, chain[k]);
    const Spline2 spline = fit.fit(pts);
    for (int l = 0; l < samples; ++l) dst[l] = spline(double(l) / double(samples - 1));
  };
  sampleChain(topology_.left_tentacle, tentacle_left_, out.tentacle_left);
  sampleChain(topology_.right_tentacle, tentacle_right_, out.tentacle_right);
}

}  // namespace creaturelab::render
