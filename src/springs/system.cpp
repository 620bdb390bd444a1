#include "springs/system.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "springs/bend.hpp"

namespace creaturelab::springs {

template <int D> System<D>::System(Network<D> network) : network_(std::move(network)) {
  const std::string problem = network_.validate();
  if (!problem.empty()) throw std::invalid_argument("spring network: " + problem);
  const int n = network_.particleCount();
  inv_mass_per_kg_.resize(n);
  inv_mass_per_coord_.assign(D * n, 0.0);
  gravity_per_coord_.assign(D * n, 0.0);
  for (int p = 0; p < n; ++p) {
    inv_mass_per_kg_[p] = network_.pinned[p] ? 0.0 : 1.0 / network_.mass_kg[p];
    for (int d = 0; d < D; ++d) {
      inv_mass_per_coord_[D * p + d] = inv_mass_per_kg_[p];
      gravity_per_coord_[D * p + d] = network_.pinned[p] ? 0.0 : network_.gravity_m_per_s2[d];
    }
  }
  for (double kd : network_.damping_ns_per_m) any_spring_damping_ = any_spring_damping_ || kd > 0;
}

// Springs (Eq. 4.14-4.15) and bends. Written as raw loops over the arrays: this is the hot path
// (one call per RK4 stage), so no Eigen temporaries and no allocation.
namespace {
// Eq. 4.14 as f_a = coef * l, f_b = -coef * l with l = x_a - x_b:
//   coef = k (r/|l| - 1) - k_d (l' . l)/|l|^2.   Coincident ends (|l| = 0) have no direction: no force.
template <int D, bool Damped>
inline void addSpring(int e, const double* l, double l2, double inv_len, const double* v, double* f, const int* sa,
                      const int* sb, const double* rest, const double* k, const double* kd) {
  if (!(l2 > 0)) return;
  double coef = k[e] * (rest[e] * inv_len - 1.0);
  if constexpr (Damped) {
    const double* va = v + D * sa[e];
    const double* vb = v + D * sb[e];
    double ldot_l = 0;
    for (int d = 0; d < D; ++d) ldot_l += (va[d] - vb[d]) * l[d];
    coef -= kd[e] * ldot_l * inv_len * inv_len;
  }
  double* fa = f + D * sa[e];
  double* fb = f + D * sb[e];
  for (int d = 0; d < D; ++d) {
    fa[d] += coef * l[d];
    fb[d] -= coef * l[d];
  }
}

// l = x_a - x_b of spring e and |l|^2, summed from 0 in axis order.
template <int D> inline double springVector(int e, const double* x, const int* sa, const int* sb, double* l) {
  const double* xa = x + D * sa[e];
  const double* xb = x + D * sb[e];
  double l2 = 0;
  for (int d = 0; d < D; ++d) {
    l[d] = xa[d] - xb[d];
    l2 += l[d] * l[d];
  }
  return l2;
}

#if defined(__SSE2__)
// 2D springs without damping (the planar web, simulate.cpp): a particle's (x, y) is one 128-bit lane pair,
// so a spring's l, l*l, coef*l and the two force updates are one packed instruction each, and springs go in
// blocks of four with two packed square roots and divisions. Every lane does the scalar loop's operation on
// the same operands (l2 = lx^2 + ly^2 is the scalar (0 + lx^2) + ly^2, as 0 + q = q exactly for q >= 0) and
// the forces are added in spring order, so the result is bit for bit that of the plain loop, and faster
// than it (and than blocks of two) on the default web. Tried without gain: keeping the last-touched
// particle's force in a register (chains of springs share a particle, but the store-to-load forwarding was
// not the bottleneck).
void planarSpringsSse2(int ns, const double* x, double* f, const int* sa, const int* sb, const double* rest,
                       const double* k) {
  const __m128d one = _mm_set1_pd(1.0);
  const __m128d zero = _mm_setzero_pd();
  int e = 0;
  for (; e + 4 <= ns; e += 4) {
    int ia[4], ib[4];
    __m128d l[4], q[4];
    for (int j = 0; j < 4; ++j) {
      ia[j] = 2 * sa[e + j];
      ib[j] = 2 * sb[e + j];
      l[j] = _mm_sub_pd(_mm_loadu_pd(x + ia[j]), _mm_loadu_pd(x + ib[j]));
      q[j] = _mm_mul_pd(l[j], l[j]);
    }
    // (|l_0|^2, |l_1|^2) and (|l_2|^2, |l_3|^2), then 1/|l| and coef = k (r/|l| - 1) two at a time.
    const __m128d l2_01 = _mm_add_pd(_mm_unpacklo_pd(q[0], q[1]), _mm_unpackhi_pd(q[0], q[1]));
    const __m128d l2_23 = _mm_add_pd(_mm_unpacklo_pd(q[2], q[3]), _mm_unpackhi_pd(q[2], q[3]));
    const __m128d inv_01 = _mm_div_pd(one, _mm_sqrt_pd(l2_01)), inv_23 = _mm_div_pd(one, _mm_sqrt_pd(l2_23));
    const __m128d c01 = _mm_mul_pd(_mm_loadu_pd(k + e), _mm_sub_pd(_mm_mul_pd(_mm_loadu_pd(rest + e), inv_01), one));
    const __m128d c23 =
        _mm_mul_pd(_mm_loadu_pd(k + e + 2), _mm_sub_pd(_mm_mul_pd(_mm_loadu_pd(rest + e + 2), inv_23), one));
    // Coincident ends (|l| = 0, or NaN) have no direction: no force.
    const int has_length =
        _mm_movemask_pd(_mm_cmpgt_pd(l2_01, zero)) | (_mm_movemask_pd(_mm_cmpgt_pd(l2_23, zero)) << 2);
    const __m128d coef[4] = {_mm_unpacklo_pd(c01, c01), _mm_unpackhi_pd(c01, c01), _mm_unpacklo_pd(c23, c23),
                             _mm_unpackhi_pd(c23, c23)};
    for (int j = 0; j < 4; ++j) {
      if (!(has_length & (1 << j))) continue;
      const __m128d fl = _mm_mul_pd(coef[j], l[j]);
      _mm_storeu_pd(f + ia[j], _mm_add_pd(_mm_loadu_pd(f + ia[j]), fl));
      _mm_storeu_pd(f + ib[j], _mm_sub_pd(_mm_loadu_pd(f + ib[j]), fl));
    }
  }
  for (; e < ns; ++e) {
    double l[2];
    const double l2 = springVector<2>(e, x, sa, sb, l);
    addSpring<2, false>(e, l, l2, 1.0 / std::sqrt(l2), nullptr, f, sa, sb, rest, k, nullptr);
  }
}
#endif

// The general loop: about 40 instructions per spring (3D). In blocks of four springs, geometry first,
// then 1/sqrt(|l|^2) as packed SSE2 square roots and divisions, then the forces in spring order: faster
// than one spring at a time on the default web, and bit for bit the same (_mm_sqrt_pd and
// _mm_div_pd are correctly rounded like their scalar forms; the accumulation order is unchanged).
// Measured and rejected (tests/bench/bench_web.cpp, BM_WebAccelerations): blocks of eight (slower);
// AVX (needs -mavx, and was no faster: the loop is bound by its loads and stores, not by the divider);
// a gather / coefficient / scatter split into passes over all springs (slower: the per-spring buffer
// costs more than it saves).
template <int D, bool Damped>
void allSprings(int ns, const double* x, const double* v, double* f, const int* sa, const int* sb, const double* rest,
                const double* k, const double* kd) {
#if defined(__SSE2__)
  if constexpr (D == 2 && !Damped) {
    planarSpringsSse2(ns, x, f, sa, sb, rest, k);
    return;
  }
#endif
  int e = 0;
#if defined(__SSE2__)
  constexpr int kBlock = 4;
  for (; e + kBlock <= ns; e += kBlock) {
    double l[kBlock][D];
    alignas(16) double l2[kBlock], inv_len[kBlock];
    for (int j = 0; j < kBlock; ++j) l2[j] = springVector<D>(e + j, x, sa, sb, l[j]);
    const __m128d one = _mm_set1_pd(1.0);
    for (int j = 0; j < kBlock; j += 2)
      _mm_store_pd(inv_len + j, _mm_div_pd(one, _mm_sqrt_pd(_mm_load_pd(l2 + j))));
    for (int j = 0; j < kBlock; ++j)
      addSpring<D, Damped>(e + j, l[j], l2[j], inv_len[j], v, f, sa, sb, rest, k, kd);
  }
#endif
  for (; e < ns; ++e) {
    double l[D];
    const double l2 = springVector<D>(e, x, sa, sb, l);
    addSpring<D, Damped>(e, l, l2, 1.0 / std::sqrt(l2), v, f, sa, sb, rest, k, kd);
  }
}
}  // namespace

template <int D> void System<D>::internalForces(const State<D>& s, Points<D>& force_n, bool with_damping) const {
  const int n = particleCount();
  if (constant_force_n_.size() > 0)
    force_n = constant_force_n_;
  else
    force_n.setZero(D, n);
  const int ns = network_.springCount();
  if (with_damping && any_spring_damping_) {
    allSprings<D, true>(ns, s.x_m.data(), s.v_m_per_s.data(), force_n.data(), network_.spring_a.data(),
                        network_.spring_b.data(), network_.rest_length_m.data(), network_.stiffness_n_per_m.data(),
                        network_.damping_ns_per_m.data());
  } else {
    allSprings<D, false>(ns, s.x_m.data(), nullptr, force_n.data(), network_.spring_a.data(),
                         network_.spring_b.data(), network_.rest_length_m.data(), network_.stiffness_n_per_m.data(),
                         network_.damping_ns_per_m.data());
  }
  const int nb = network_.bendCount();
  for (int e = 0; e < nb; ++e) {
    const int i = network_.bend_i[e], j = network_.bend_j[e], kk = network_.bend_k[e];
    const Vec<D> a = s.x_m.col(j) - s.x_m.col(i);
    const Vec<D> b = s.x_m.col(kk) - s.x_m.col(j);
    const AngleGradient<D> g = angleGradient<D>(a, b);
    // f = -dE/dx, E = 0.5 kb (theta - theta0)^2, a = x_j - x_i, b = x_k - x_j.
    const double torque = network_.bend_stiffness_nm_per_rad[e] * bendDeviation<D>(g.theta, network_.rest_angle_rad[e]);
    force_n.col(i) += torque * g.d_da;
    force_n.col(j) -= torque * (g.d_da - g.d_db);
    force_n.col(kk) -= torque * g.d_db;
  }
}

template <int D> void System<D>::setConstantForce(Points<D> force_n) {
  if (force_n.size() > 0 && force_n.cols() != particleCount())
    throw std::invalid_argument("constant force has " + std::to_string(force_n.cols()) + " columns for " +
                                std::to_string(particleCount()) + " particles");
  if (!force_n.allFinite()) throw std::invalid_argument("constant force has a non-finite entry");
  constant_force_n_ = std::move(force_n);
}

template <int D> void System<D>::forces(const State<D>& s, double t_s, Points<D>& force_n) const {
  internalForces(s, force_n);
  if (external_) external_(t_s, s, force_n);
  const int n = particleCount();
  const Vec<D> g = network_.gravity_m_per_s2;
  const double drag = network_.drag_ns_per_m;
  for (int p = 0; p < n; ++p) {
    if (network_.pinned[p]) {
      force_n.col(p).setZero();
    } else {
      // Eq. 4.6 (gravity) and Eq. 4.7 (drag).
      force_n.col(p) += network_.mass_kg[p] * g - drag * s.v_m_per_s.col(p);
    }
  }
}

template <int D> void System<D>::conservativeForces(const State<D>& s, Points<D>& force_n) const {
  internalForces(s, force_n, /*with_damping=*/false);
  for (int p = 0; p < particleCount(); ++p) {
    if (network_.pinned[p])
      force_n.col(p).setZero();
    else
      force_n.col(p) += network_.mass_kg[p] * network_.gravity_m_per_s2;
  }
}

template <int D> void System<D>::accelerations(const State<D>& s, double t_s, Points<D>& acc) const {
  acc.resize(D, particleCount());  // sized now so the pointer below stays valid
  double* out = acc.data();          // holds the forces until the pass reads particle p's
  accelerationsThen(s, t_s, acc, [out](int i, double a) { out[i] = a; });
}

template <int D> double System<D>::kineticEnergy(const State<D>& s) const {
  double e = 0;
  for (int p = 0; p < particleCount(); ++p) e += 0.5 * network_.mass_kg[p] * s.v_m_per_s.col(p).squaredNorm();
  return e;
}

template <int D> double System<D>::elasticEnergy(const State<D>& s) const {
  double e = 0;
  for (int k = 0; k < network_.springCount(); ++k) {
    const double stretch =
        (s.x_m.col(network_.spring_a[k]) - s.x_m.col(network_.spring_b[k])).norm() - network_.rest_length_m[k];
    e += 0.5 * network_.stiffness_n_per_m[k] * stretch * stretch;
  }
  for (int k = 0; k < network_.bendCount(); ++k) {
    const Vec<D> a = s.x_m.col(network_.bend_j[k]) - s.x_m.col(network_.bend_i[k]);
    const Vec<D> b = s.x_m.col(network_.bend_k[k]) - s.x_m.col(network_.bend_j[k]);
    const double dtheta = bendDeviation<D>(bendAngle<D>(a, b), network_.rest_angle_rad[k]);
    e += 0.5 * network_.bend_stiffness_nm_per_rad[k] * dtheta * dtheta;
  }
  return e;
}

template <int D> double System<D>::gravityEnergy(const State<D>& s) const {
  double e = 0;
  for (int p = 0; p < particleCount(); ++p) e -= network_.mass_kg[p] * network_.gravity_m_per_s2.dot(s.x_m.col(p));
  return e;
}

template <int D> double System<D>::constantForceEnergy(const State<D>& s) const {
  double e = 0;
  if (constant_force_n_.size() == 0) return e;
  for (int p = 0; p < particleCount(); ++p)
    if (!network_.pinned[p]) e -= constant_force_n_.col(p).dot(s.x_m.col(p));
  return e;
}

template <int D> double System<D>::potentialEnergy(const State<D>& s) const {
  return elasticEnergy(s) + gravityEnergy(s) + constantForceEnergy(s);
}

namespace {
// Appends scale * block at (D*row_particle, D*col_particle) unless the row particle is pinned.
template <int D, class Block>
void addBlock(const std::vector<uint8_t>& pinned, int row_particle, int col_particle, const Block& block, double scale,
              std::vector<Eigen::Triplet<double>>& out) {
  if (pinned[row_particle]) return;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) out.emplace_back(D * row_particle + r, D * col_particle + c, scale * block(r, c));
}
}  // namespace

template <int D>
void System<D>::addStiffnessTriplets(const State<D>& s, double scale, std::vector<Eigen::Triplet<double>>& out,
                                     bool clamp_compression) const {
  using Mat = Eigen::Matrix<double, D, D>;
  const auto& pinned = network_.pinned;
  for (int e = 0; e < network_.springCount(); ++e) {
    const int a = network_.spring_a[e], b = network_.spring_b[e];
    const Vec<D> l = s.x_m.col(a) - s.x_m.col(b);
    const double len = l.norm();
    Mat block = Mat::Zero();  // B = k u u^T + k (1 - r/|l|) (I - u u^T);  df_a/dx_a = -B, df_a/dx_b = B
    if (len > 0) {
      const Vec<D> u = l / len;
      const double k = network_.stiffness_n_per_m[e];
      double transverse = 1.0 - network_.rest_length_m[e] / len;
      if (clamp_compression && transverse < 0) transverse = 0;
      block = k * transverse * Mat::Identity() + k * (1.0 - transverse) * u * u.transpose();
    }
    addBlock<D>(pinned, a, a, block, -scale, out);
    addBlock<D>(pinned, a, b, block, scale, out);
    addBlock<D>(pinned, b, a, block, scale, out);
    addBlock<D>(pinned, b, b, block, -scale, out);
  }
  for (int e = 0; e < network_.bendCount(); ++e) {
    const int idx[3] = {network_.bend_i[e], network_.bend_j[e], network_.bend_k[e]};
    const Vec<D> a = s.x_m.col(idx[1]) - s.x_m.col(idx[0]);
    const Vec<D> b = s.x_m.col(idx[2]) - s.x_m.col(idx[1]);
    const Eigen::Matrix<double, 3 * D, 3 * D> h = bendEnergyHessian<D>(
        a, b, network_.rest_angle_rad[e], network_.bend_stiffness_nm_per_rad[e], clamp_compression);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        addBlock<D>(pinned, idx[r], idx[c], h.template block<D, D>(D * r, D * c), -scale, out);
  }
}

template <int D>
void System<D>::addDampingTriplets(const State<D>& s, double scale, std::vector<Eigen::Triplet<double>>& out) const {
  using Mat = Eigen::Matrix<double, D, D>;
  const auto& pinned = network_.pinned;
  for (int e = 0; e < network_.springCount(); ++e) {
    const double kd = network_.damping_ns_per_m[e];
    if (kd == 0) continue;
    const int a = network_.spring_a[e], b = network_.spring_b[e];
    const Vec<D> l = s.x_m.col(a) - s.x_m.col(b);
    const double len = l.norm();
    Mat block = Mat::Zero();  // df_a/dv_a = -k_d u u^T (Eq. 4.14)
    if (len > 0) block = kd * (l / len) * (l / len).transpose();
    addBlock<D>(pinned, a, a, block, -scale, out);
    addBlock<D>(pinned, a, b, block, scale, out);
    addBlock<D>(pinned, b, a, block, scale, out);
    addBlock<D>(pinned, b, b, block, -scale, out);
  }
  const double drag = network_.drag_ns_per_m;
  if (drag != 0) {
    for (int p = 0; p < particleCount(); ++p) {
      if (pinned[p]) continue;
      for (int d = 0; d < D; ++d) out.emplace_back(D * p + d, D * p + d, -scale * drag);  // Eq. 4.7
    }
  }
}

template class System<2>;
template class System<3>;

}  // namespace creaturelab::springs
