#include "ib/transfer.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace creaturelab::ib {
namespace {

std::string show(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

std::string markerName(std::size_t k, fluid::Vec2 p) {
  return "immersed-boundary marker " + std::to_string(k) + " at (" + show(p.x) + ", " + show(p.y) + ") m";
}

// One axis of a stencil. xs is the position in face-index units (x / dx for u faces along x,
// x / dx − 1/2 for v faces along x, and alike along y). The stencil starts at face
// floor(xs) − s/2 + 1 (kernel_weights_1d); it must lie within the faces first_face..last_face.
// Bounds are compared as doubles before any conversion to int, so that a huge position cannot
// overflow the cast. False if the stencil does not fit.
bool axisStencil(Kernel kernel, int scale, int support, double xs, int first_face, int last_face, int& start,
                  double (&weights)[kMaxStencilFaces]) {
  const double f = std::floor(xs);
  const double first = f - static_cast<double>(support / 2 - 1);
  if (!(first >= first_face && first + static_cast<double>(support - 1) <= last_face)) return false;
  start = static_cast<int>(first);
  stretchedKernelWeights_1d(kernel, scale, xs - f, weights);
  return true;
}

// Σ_k value(k) wx[a] wy[b] into face (i0 + a, j0 + b), for one component (S = stencil faces; a
// compile-time S for the common widths, so that the inner loops unroll). at(i, j) points to face
// (i, j) of the field written, whose row runs on from it: a whole face field or a patch of one.
template <int S = 0, class Value, class At>
void spreadComponent(const std::vector<FaceStencil>& stencils, Value value, At at, int support = S) {
  if constexpr (S != 0) support = S;
  for (std::size_t k = 0; k < stencils.size(); ++k) {
    const FaceStencil& s = stencils[k];
    const double density = value(k);
    for (int b = 0; b < support; ++b) {
      double* row = at(s.i0, s.j0 + b);
      const double row_density = density * s.wy[b];
      for (int a = 0; a < support; ++a) row[a] += row_density * s.wx[a];
    }
  }
}

// store(k, Σ_b wy[b] Σ_a wx[a] u(i0 + a, j0 + b)), for one component (S and at as in spread_component).
template <int S = 0, class At, class Store>
void interpolateComponent(const std::vector<FaceStencil>& stencils, At at, Store store, int support = S) {
  if constexpr (S != 0) support = S;
  for (std::size_t k = 0; k < stencils.size(); ++k) {
    const FaceStencil& s = stencils[k];
    double sum = 0.0;
    for (int b = 0; b < support; ++b) {
      const double* row = at(s.i0, s.j0 + b);
      double row_sum = 0.0;
      for (int a = 0; a < support; ++a) row_sum += s.wx[a] * row[a];
      sum += s.wy[b] * row_sum;
    }
    store(k, sum);
  }
}

// Face (i, j) of a face field.
auto facesOf(fluid::Array2& field) {
  return [&field](int i, int j) { return field.row(j) + i; };
}
auto facesOf(const fluid::Array2& field) {
  return [&field](int i, int j) { return field.row(j) + i; };
}

void requireShape(const fluid::Array2& a, int nx, int ny, const char* what) {
  if (a.nx() != nx || a.ny() != ny) {
    throw std::invalid_argument(std::string("immersed-boundary transfer: ") + what + " is " + std::to_string(a.nx()) +
                                " x " + std::to_string(a.ny()) + " faces, but the located grid has " +
                                std::to_string(nx) + " x " + std::to_string(ny));
  }
}

void requireCount(std::size_t got, int markers, const char* what) {
  if (got != static_cast<std::size_t>(markers)) {
    throw std::invalid_argument(std::string("immersed-boundary transfer: ") + std::to_string(got) + " " + what +
                                " for " + std::to_string(markers) + " located markers");
  }
}

}  // namespace

namespace {
// axis_stencil for a marker stretched `scale` times inside a stencil `support` faces wide (its own
// stencilFaces(kernel, scale) ≤ support): its faces centred in the wide window, zero weights around.
bool paddedAxisStencil(Kernel kernel, int scale, int support, double xs, int first_face, int last_face, int& start,
                         double (&weights)[kMaxStencilFaces]) {
  const int own = stencilFaces(kernel, scale);
  if (own == support) return axisStencil(kernel, scale, support, xs, first_face, last_face, start, weights);
  const int pad = (support - own) / 2;  // both even: support − own is even
  double narrow[kMaxStencilFaces] = {};
  if (!axisStencil(kernel, scale, own, xs, first_face + pad, last_face - pad, start, narrow)) return false;
  start -= pad;
  for (int a = 0; a < kMaxStencilFaces; ++a) weights[a] = 0.0;
  for (int a = 0; a < own; ++a) weights[pad + a] = narrow[a];
  return true;
}
}  // namespace

void Transfer::locate(const fluid::MacGrid2& grid, Kernel kernel, std::span<const fluid::Vec2> positions_m,
                      int kernel_scale, std::span<const int> marker_scales) {
  u_stencils_.clear();  // keeps the capacity: no allocation once the largest marker count was seen
  v_stencils_.clear();
  if (grid.nx < 1 || grid.ny < 1 || !(std::isfinite(grid.dx_m) && grid.dx_m > 0.0)) {
    throw std::invalid_argument("immersed-boundary transfer: the fluid grid must have cells of positive size (got " +
                                std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + " cells of " +
                                show(grid.dx_m) + " m)");
  }
  if (!marker_scales.empty() && marker_scales.size() != positions_m.size())
    throw std::invalid_argument("immersed-boundary transfer: " + std::to_string(marker_scales.size()) +
                                " kernel stretches for " + std::to_string(positions_m.size()) + " markers");
  int widest = kernel_scale;
  if (!marker_scales.empty()) widest = *std::max_element(marker_scales.begin(), marker_scales.end());
  for (const int s : marker_scales) ib::stencilFaces(kernel, s);  // throws for a scale out of range
  support_ = ib::stencilFaces(kernel, widest);  // throws for a scale out of range
  kernel_ = kernel;
  scale_ = widest;
  nx_ = grid.nx;
  ny_ = grid.ny;
  dx_m_ = grid.dx_m;
  inv_cell_area_per_m2_ = 1.0 / (grid.dx_m * grid.dx_m);

  u_stencils_.resize(positions_m.size());
  v_stencils_.resize(positions_m.size());
  for (std::size_t k = 0; k < positions_m.size(); ++k) {
    const fluid::Vec2 p = positions_m[k];
    if (!(std::isfinite(p.x) && std::isfinite(p.y))) {
      u_stencils_.clear();
      v_stencils_.clear();
      throw std::invalid_argument(markerName(k, p) + " is not finite");
    }
    const double xs = p.x / grid.dx_m;  // position in cell units
    const double ys = p.y / grid.dx_m;
    FaceStencil& u = u_stencils_[k];
    FaceStencil& v = v_stencils_[k];
    // u faces at (i, j + 1/2) cells: interior faces i = 1..nx−1, all rows j = 0..ny−1.
    // v faces at (i + 1/2, j) cells: all columns i = 0..nx−1, interior faces j = 1..ny−1.
    const int m = marker_scales.empty() ? scale_ : marker_scales[k];
    const bool fits = paddedAxisStencil(kernel, m, support_, xs, 1, nx_ - 1, u.i0, u.wx) &&
                      paddedAxisStencil(kernel, m, support_, ys - 0.5, 0, ny_ - 1, u.j0, u.wy) &&
                      paddedAxisStencil(kernel, m, support_, xs - 0.5, 0, nx_ - 1, v.i0, v.wx) &&
                      paddedAxisStencil(kernel, m, support_, ys, 1, ny_ - 1, v.j0, v.wy);
    if (!fits) {
      u_stencils_.clear();
      v_stencils_.clear();
      const int reach = support_ / 2;
      const double margin_m = reach * grid.dx_m;
      throw std::invalid_argument(
          markerName(k, p) + " is within " + std::to_string(reach) + (reach == 1 ? " cell" : " cells") +
          " of the domain wall: the " + std::string(to_string(kernel)) + " kernel" +
          (scale_ > 1 ? " stretched " + std::to_string(scale_) + " times" : std::string()) + " reaches " +
          std::to_string(reach) +
          " cells around a marker, so markers must stay in [" + show(margin_m) + ", " +
          show(grid.width_m() - margin_m) + ") x [" + show(margin_m) + ", " + show(grid.height_m() - margin_m) +
          ") m (cell size " + show(grid.dx_m) + " m)");
    }
  }
}

void Transfer::spread(std::span<const fluid::Vec2> forces_n_per_m,
                      fluid::FaceVectorField2& force_density_n_per_m3) const {
  requireCount(forces_n_per_m.size(), markerCount(), "forces");
  if (markerCount() == 0) return;
  requireShape(force_density_n_per_m3.x, nx_ + 1, ny_, "the x force density (u faces)");
  requireShape(force_density_n_per_m3.y, nx_, ny_ + 1, "the y force density (v faces)");
  const double inv_area = inv_cell_area_per_m2_;
  const auto fx = [&](std::size_t k) { return forces_n_per_m[k].x * inv_area; };
  const auto fy = [&](std::size_t k) { return forces_n_per_m[k].y * inv_area; };
  auto& density_x = force_density_n_per_m3.x;
  auto& density_y = force_density_n_per_m3.y;
  if (support_ == 2) {
    spreadComponent<2>(u_stencils_, fx, facesOf(density_x));
    spreadComponent<2>(v_stencils_, fy, facesOf(density_y));
  } else if (support_ == 4) {
    spreadComponent<4>(u_stencils_, fx, facesOf(density_x));
    spreadComponent<4>(v_stencils_, fy, facesOf(density_y));
  } else {
    spreadComponent(u_stencils_, fx, facesOf(density_x), support_);
    spreadComponent(v_stencils_, fy, facesOf(density_y), support_);
  }
}

void Transfer::interpolate(const fluid::MacGrid2& grid, std::span<fluid::Vec2> velocities_m_per_s) const {
  requireCount(velocities_m_per_s.size(), markerCount(), "velocities");
  if (markerCount() == 0) return;
  if (grid.nx != nx_ || grid.ny != ny_ || grid.dx_m != dx_m_) {
    throw std::invalid_argument("immersed-boundary transfer: interpolating on a grid of " + std::to_string(grid.nx) +
                                " x " + std::to_string(grid.ny) + " cells of " + show(grid.dx_m) +
                                " m, but the markers were located on " + std::to_string(nx_) + " x " +
                                std::to_string(ny_) + " cells of " + show(dx_m_) + " m");
  }
  requireShape(grid.u_m_per_s, nx_ + 1, ny_, "the u velocity");
  requireShape(grid.v_m_per_s, nx_, ny_ + 1, "the v velocity");
  const auto ux = [&](std::size_t k, double sum) { velocities_m_per_s[k].x = sum; };
  const auto uy = [&](std::size_t k, double sum) { velocities_m_per_s[k].y = sum; };
  if (support_ == 2) {
    interpolateComponent<2>(u_stencils_, facesOf(grid.u_m_per_s), ux);
    interpolateComponent<2>(v_stencils_, facesOf(grid.v_m_per_s), uy);
  } else if (support_ == 4) {
    interpolateComponent<4>(u_stencils_, facesOf(grid.u_m_per_s), ux);
    interpolateComponent<4>(v_stencils_, facesOf(grid.v_m_per_s), uy);
  } else {
    interpolateComponent(u_stencils_, facesOf(grid.u_m_per_s), ux, support_);
    interpolateComponent(v_stencils_, facesOf(grid.v_m_per_s), uy, support_);
  }
}

namespace {

// Σ_a w_k[a] w_l[a + shift] over the stencil offsets a that both cover (0 ≤ a + shift < support),
// ascending: term for term the loop over all a that skips the others, without its branch.
double overlap1d(const double* wk, const double* wl, int shift, int support) {
  const int lo = std::max(0, -shift), hi = std::min(support, support - shift);
  double sum = 0.0;
  for (int a = lo; a < hi; ++a) sum += wk[a] * wl[a + shift];
  return sum;
}

// The markers of one face family by the first face column of their stencils, and within a column
// by the first face row (a counting sort by column, then a sort by row): gram() finds, for each
// marker, the markers whose stencils start within support − 1 faces of its own on both axes by a
// binary search in each nearby column, instead of testing all n.
struct StencilColumns {
  int first = 0;                  // the smallest i0
  std::vector<int> begin;         // markers of column first + c: order[begin[c] .. begin[c + 1])
  std::vector<int> order;
  std::vector<int> row;           // row[p] = j0 of marker order[p], ascending within a column

  explicit StencilColumns(const std::vector<FaceStencil>& st) : order(st.size()), row(st.size()) {
    if (st.empty()) return;
    int last = st[0].i0;
    first = st[0].i0;
    for (const FaceStencil& s : st) first = std::min(first, s.i0), last = std::max(last, s.i0);
    begin.assign(static_cast<std::size_t>(last - first + 2), 0);
    for (const FaceStencil& s : st) ++begin[static_cast<std::size_t>(s.i0 - first + 1)];
    for (std::size_t c = 1; c < begin.size(); ++c) begin[c] += begin[c - 1];
    std::vector<int> next(begin.begin(), begin.end() - 1);
    for (int k = 0; k < static_cast<int>(st.size()); ++k) order[static_cast<std::size_t>(next[st[k].i0 - first]++)] = k;
    for (std::size_t c = 0; c + 1 < begin.size(); ++c)
      std::sort(order.begin() + begin[c], order.begin() + begin[c + 1],
                [&](int a, int b) { return st[a].j0 < st[b].j0 || (st[a].j0 == st[b].j0 && a < b); });
    for (std::size_t p = 0; p < order.size(); ++p) row[p] = st[order[p]].j0;
  }
};

// G's entries on and below the diagonal (k ≥ l) of one face family, column by column, rows ascending:
// column l at [begin[l], begin[l + 1]) of row and value.
struct LowerColumns {
  std::vector<int> begin, row;
  std::vector<double> value;
};

LowerColumns lowerColumns(const std::vector<FaceStencil>& st, int support, double scale) {
  const int n = static_cast<int>(st.size());
  const StencilColumns cols(st);
  LowerColumns lower;
  lower.begin.reserve(static_cast<std::size_t>(n) + 1);
  lower.begin.push_back(0);
  // The overlapping markers of one marker as a bit set over the marker indices, read out in
  // ascending order (a few words per marker, where sorting the list cost more than the search).
  std::vector<std::uint64_t> near(static_cast<std::size_t>(n + 63) / 64);
  const int last = cols.first + static_cast<int>(cols.begin.size()) - 2;
  for (int l = 0; l < n; ++l) {
    std::fill(near.begin(), near.end(), 0);
    for (int i = std::max(cols.first, st[l].i0 - support + 1); i <= std::min(last, st[l].i0 + support - 1); ++i) {
      const auto rows_begin = cols.row.begin() + cols.begin[i - cols.first];
      const auto rows_end = cols.row.begin() + cols.begin[i - cols.first + 1];
      auto p = std::lower_bound(rows_begin, rows_end, st[l].j0 - support + 1);
      for (; p != rows_end && *p < st[l].j0 + support; ++p) {
        const int k = cols.order[static_cast<std::size_t>(p - cols.row.begin())];
        near[static_cast<std::size_t>(k) / 64] |= std::uint64_t{1} << (k % 64);
      }
    }
    near[static_cast<std::size_t>(l) / 64] &= ~std::uint64_t{0} << (l % 64);  // k ≥ l
    for (std::size_t w = static_cast<std::size_t>(l) / 64; w < near.size(); ++w)
      for (std::uint64_t bits = near[w]; bits != 0; bits &= bits - 1) {
        const int k = static_cast<int>(64 * w) + std::countr_zero(bits);
        const int di = st[k].i0 - st[l].i0, dj = st[k].j0 - st[l].j0;
        lower.row.push_back(k);
        lower.value.push_back(scale * overlap1d(st[k].wx, st[l].wx, di, support) *
                              overlap1d(st[k].wy, st[l].wy, dj, support));
      }
    lower.begin.push_back(static_cast<int>(lower.row.size()));
  }
  return lower;
}

// One component's G x: x spread onto a zeroed patch just covering its stencils and read back
// through them (spread_component, interpolate_component), in marker order both times.
template <int S = 0>
void applyGramComponent(const std::vector<FaceStencil>& st, int c, const double* x, double* out,
                          std::vector<double>& patch, int support = S) {
  if constexpr (S != 0) support = S;
  int i_lo = st[0].i0, i_hi = st[0].i0, j_lo = st[0].j0, j_hi = st[0].j0;
  for (const FaceStencil& s : st) {
    i_lo = std::min(i_lo, s.i0), i_hi = std::max(i_hi, s.i0);
    j_lo = std::min(j_lo, s.j0), j_hi = std::max(j_hi, s.j0);
  }
  const long width = i_hi - i_lo + support;
  patch.assign(static_cast<std::size_t>(width * (j_hi - j_lo + support)), 0.0);
  const auto at = [&](int i, int j) { return patch.data() + (j - j_lo) * width + (i - i_lo); };
  spreadComponent<S>(st, [&](std::size_t k) { return x[2 * k + c]; }, at, support);
  interpolateComponent<S>(st, at, [&](std::size_t k, double sum) { out[2 * k + c] = sum; }, support);
}

}  // namespace

void Transfer::applyGram(std::span<const double> x, std::span<double> out, std::vector<double>& patch) const {
  const std::size_t n = 2 * static_cast<std::size_t>(markerCount());
  if (x.size() != n || out.size() != n)
    throw std::invalid_argument("immersed-boundary transfer: apply_gram takes vectors of twice the " +
                                std::to_string(markerCount()) + " located markers");
  if (n == 0) return;
  for (int c = 0; c < 2; ++c) {
    const std::vector<FaceStencil>& st = c == 0 ? u_stencils_ : v_stencils_;
    if (support_ == 4)
      applyGramComponent<4>(st, c, x.data(), out.data(), patch);
    else if (support_ == 8)
      applyGramComponent<8>(st, c, x.data(), out.data(), patch);
    else
      applyGramComponent(st, c, x.data(), out.data(), patch, support_);
  }
}

// Column by column, rows ascending, written straight into the compressed storage. G(k, l) and
// G(l, k) sum the same products in the same order (overlap1d with the stencils swapped and the shift
// negated meets w_k[a] w_l[a + shift] at the same a), so G is exactly symmetric and each entry above
// the diagonal is the mirror of one below it: only those on and below are computed, the ones above
// copied from them (about a third fewer instructions a call).
void Transfer::gram(double scale, Eigen::SparseMatrix<double>& out) const {
  const int n = markerCount();
  const LowerColumns lower[2] = {lowerColumns(u_stencils_, support_, scale),
                                 lowerColumns(v_stencils_, support_, scale)};
  // above[c][l]: entries of column l above the diagonal, one for each k < l with (l, k) below it.
  std::vector<int> above[2] = {std::vector<int>(n, 0), std::vector<int>(n, 0)};
  for (int c = 0; c < 2; ++c)
    for (int l = 0; l < n; ++l)
      for (int p = lower[c].begin[l]; p < lower[c].begin[l + 1]; ++p)
        if (lower[c].row[p] != l) ++above[c][lower[c].row[p]];
  out.resize(2 * n, 2 * n);
  int* outer = out.outerIndexPtr();
  outer[0] = 0;
  for (int l = 0; l < n; ++l)
    for (int c = 0; c < 2; ++c)
      outer[2 * l + c + 1] = outer[2 * l + c] + above[c][l] + (lower[c].begin[l + 1] - lower[c].begin[l]);
  out.resizeNonZeros(outer[2 * n]);
  int* inner = out.innerIndexPtr();
  double* value = out.valuePtr();
  // next[2 k + c]: where column 2 k + c's next entry above the diagonal goes; l ascending, so its
  // rows ascend, and they all come before its diagonal.
  std::vector<int> next(outer, outer + 2 * n);
  for (int l = 0; l < n; ++l)
    for (int c = 0; c < 2; ++c) {
      const LowerColumns& lc = lower[c];
      int at = outer[2 * l + c] + above[c][l];
      for (int p = lc.begin[l]; p < lc.begin[l + 1]; ++p, ++at) {
        const int k = lc.row[p];
        inner[at] = 2 * k + c;
        value[at] = lc.value[p];
        if (k == l) continue;
        const int mirror = next[2 * k + c]++;
        inner[mirror] = 2 * l + c;
        value[mirror] = lc.value[p];
      }
    }
}

void Transfer::gram(Eigen::MatrixXd& g) const {
  Eigen::SparseMatrix<double> sparse;
  gram(1.0, sparse);
  g = Eigen::MatrixXd(sparse);
}

}  // namespace creaturelab::ib
