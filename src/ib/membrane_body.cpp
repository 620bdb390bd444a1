#include "ib/membrane_body.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace creaturelab::ib {

namespace {

void addProblem(std::string& out, const std::string& text) { out += (out.empty() ? "" : "; ") + text; }

// The ring's own rules (MembraneParams and MembraneBody): a closed ring of 3 or more markers, a
// positive stiffness.
std::string ringProblems(int markers, double stiffness_n_per_m) {
  std::string out;
  if (markers < 3) addProblem(out, "a closed membrane needs at least 3 markers (got " + std::to_string(markers) + ")");
  if (!(stiffness_n_per_m > 0) || !std::isfinite(stiffness_n_per_m))
    addProblem(out, "the membrane's stiffness must be a positive number of N/m per metre of depth");
  return out;
}

}  // namespace

std::string MembraneParams::validate() const {
  std::string out;
  if (!std::isfinite(centre_x_m) || !std::isfinite(centre_y_m)) addProblem(out, "the membrane's centre must be finite");
  if (!(semi_axis_x_m > 0) || !std::isfinite(semi_axis_x_m) || !(semi_axis_y_m > 0) || !std::isfinite(semi_axis_y_m))
    addProblem(out, "the membrane's semi-axes must be positive lengths in metres");
  if (const std::string ring = ringProblems(markers, stiffness_n_per_m); !ring.empty()) addProblem(out, ring);
  return out;
}

std::vector<fluid::Vec2> ellipseMarkers(const MembraneParams& p) {
  if (const std::string err = p.validate(); !err.empty()) throw std::invalid_argument(err);
  const double a = p.semi_axis_x_m, b = p.semi_axis_y_m;
  // Cumulative arc length s(θ_j) at θ_j = 2π j / M, midpoint rule on each sub-interval:
  //   ds/dθ = sqrt(a² sin²θ + b² cos²θ).
  const int sub = 64 * p.markers;
  const double h = 2.0 * M_PI / sub;
  std::vector<double> s(static_cast<std::size_t>(sub) + 1, 0.0);
  for (int j = 0; j < sub; ++j) {
    const double t = (j + 0.5) * h;
    s[j + 1] = s[j] + h * std::hypot(a * std::sin(t), b * std::cos(t));
  }
  const double perimeter = s[sub];
  std::vector<fluid::Vec2> out;
  out.reserve(p.markers);
  int j = 0;
  for (int k = 0; k < p.markers; ++k) {
    // θ where s(θ) = k L / N, linear between the tabulated points.
    const double target = perimeter * k / p.markers;
    while (j + 1 < sub && s[j + 1] <= target) ++j;
    const double theta = (j + (target - s[j]) / (s[j + 1] - s[j])) * h;
    out.push_back({p.centre_x_m + a * std::cos(theta), p.centre_y_m + b * std::sin(theta)});
  }
  return out;
}

MembraneBody::MembraneBody(int markers, double stiffness_n_per_m) : markers_(markers), k_(stiffness_n_per_m) {
  if (const std::string err = ringProblems(markers, stiffness_n_per_m); !err.empty()) throw std::invalid_argument(err);
}

void MembraneBody::forces(double /*t_s*/, std::span<const fluid::Vec2> x, std::span<fluid::Vec2> force) const {
  const int n = markers_;
  for (int k = 0; k < n; ++k) {
    const fluid::Vec2& prev = x[(k + n - 1) % n];
    const fluid::Vec2& next = x[(k + 1) % n];
    // k (X_{k+1} − X_k) + k (X_{k−1} − X_k): the pulls of the two segments at marker k.
    force[k] = {k_ * ((next.x - x[k].x) + (prev.x - x[k].x)), k_ * ((next.y - x[k].y) + (prev.y - x[k].y))};
  }
}

void MembraneBody::stiffness(double /*t_s*/, std::span<const fluid::Vec2> /*x*/, double scale,
                             std::vector<Eigen::Triplet<double>>& out) const {
  // ∂F_k/∂X_k = −2k I, ∂F_k/∂X_{k±1} = k I (the ring Laplacian times k, on each axis alone).
  const int n = markers_;
  const double diagonal = -2.0 * scale * k_, neighbour = scale * k_;
  for (int k = 0; k < n; ++k)
    for (int axis = 0; axis < 2; ++axis) {
      const int row = 2 * k + axis;
      out.emplace_back(row, row, diagonal);
      out.emplace_back(row, 2 * ((k + 1) % n) + axis, neighbour);
      out.emplace_back(row, 2 * ((k + n - 1) % n) + axis, neighbour);
    }
}

double MembraneBody::elasticEnergy(std::span<const fluid::Vec2> x) const {
  double sum = 0;
  for (int k = 0; k < markers_; ++k) {
    const fluid::Vec2& next = x[(k + 1) % markers_];
    const double dx = next.x - x[k].x, dy = next.y - x[k].y;
    sum += dx * dx + dy * dy;
  }
  return 0.5 * k_ * sum;
}

double MembraneBody::meanTension(std::span<const fluid::Vec2> x) const {
  double sum = 0;
  for (int k = 0; k < markers_; ++k) {
    const fluid::Vec2& next = x[(k + 1) % markers_];
    sum += std::hypot(next.x - x[k].x, next.y - x[k].y);
  }
  return k_ * sum / markers_;
}

PolygonShape polygonShape(std::span<const fluid::Vec2> x) {
  PolygonShape shape;
  const std::size_t n = x.size();
  if (n == 0) return shape;
  // Moments about the mean vertex (o), which keeps the round-off of the sums small:
  //   A = ½ Σ c_i,  ∫x dA = ⅙ Σ (x_i + x_{i+1}) c_i,  ∫x² dA = 1/12 Σ (x_i² + x_i x_{i+1} + x_{i+1}²) c_i,
  //   ∫xy dA = 1/24 Σ (x_i y_{i+1} + 2 x_i y_i + 2 x_{i+1} y_{i+1} + x_{i+1} y_i) c_i,
  // with c_i = x_i y_{i+1} − x_{i+1} y_i (Green's theorem on each edge).
  double ox = 0, oy = 0;
  for (const auto& p : x) {
    ox += p.x;
    oy += p.y;
  }
  ox /= double(n);
  oy /= double(n);
  double area2 = 0, mx = 0, my = 0, ixx = 0, iyy = 0, ixy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const fluid::Vec2& p = x[i];
    const fluid::Vec2& q = x[(i + 1) % n];
    const double x0 = p.x - ox, y0 = p.y - oy, x1 = q.x - ox, y1 = q.y - oy;
    const double c = x0 * y1 - x1 * y0;
    area2 += c;
    mx += (x0 + x1) * c;
    my += (y0 + y1) * c;
    ixx += (x0 * x0 + x0 * x1 + x1 * x1) * c;
    iyy += (y0 * y0 + y0 * y1 + y1 * y1) * c;
    ixy += (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * c;
    shape.perimeter_m += std::hypot(q.x - p.x, q.y - p.y);
  }
  const double area = 0.5 * area2;
  shape.area_m2 = area;
  const double cx = mx / (6 * area), cy = my / (6 * area);
  shape.centroid_m = {ox + cx, oy + cy};
  // Central second moments per unit area (the sign of A cancels): the covariance of the region.
  const double sxx = ixx / (12 * area) - cx * cx;
  const double syy = iyy / (12 * area) - cy * cy;
  const double sxy = ixy / (24 * area) - cx * cy;
  const double mean = 0.5 * (sxx + syy);
  const double radius = std::hypot(0.5 * (sxx - syy), sxy);
  const double lo = mean - radius, hi = mean + radius;
  shape.aspect_ratio = lo > 0 ? std::sqrt(hi / lo) : std::nan("");
  return shape;
}

}  // namespace creaturelab::ib
