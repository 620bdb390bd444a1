#include "springs/provot.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace creaturelab::springs {

std::string ProvotOptions::validate() const {
  std::ostringstream msg;
  if (!(max_strain >= 0) || !std::isfinite(max_strain)) {
    msg << "provot max_strain is " << max_strain << "; it must be zero or positive";
  } else if (passes < 1) {
    msg << "provot passes is " << passes << "; at least one pass is needed";
  } else if (!(tolerance >= 0 && tolerance <= 1e-3)) {
    msg << "provot tolerance is " << tolerance << "; it must lie in [0, 1e-3]";
  }
  return msg.str();
}

namespace {

// One sweep in spring index order. Returns the number of springs shortened; worst_strain gets the
// largest strain seen before any correction of that spring in this sweep.
template <int D>
long sweep(const Network<D>& network, double max_strain, double tolerance, State<D>& s, double& worst_strain) {
  long corrected = 0;
  worst_strain = 0;
  for (int e = 0; e < network.springCount(); ++e) {
    const int a = network.spring_a[e], b = network.spring_b[e];
    const bool free_a = !network.pinned[a], free_b = !network.pinned[b];
    const Vec<D> l = s.x_m.col(a) - s.x_m.col(b);
    const double len = l.norm();
    const double rest = network.rest_length_m[e];
    const double max_len = (1.0 + max_strain) * rest;
    const double strain = (len - rest) / rest;
    worst_strain = e == 0 ? strain : std::max(worst_strain, strain);
    if (!(len > max_len * (1.0 + tolerance)) || (!free_a && !free_b)) continue;
    // Keep the direction (Provot: the direction of motion is taken as right), cut the excess.
    const Vec<D> shift = (len - max_len) / len * l;
    if (free_a && free_b) {
      s.x_m.col(a) -= 0.5 * shift;
      s.x_m.col(b) += 0.5 * shift;
    } else if (free_a) {
      s.x_m.col(a) -= shift;
    } else {
      s.x_m.col(b) += shift;
    }
    ++corrected;
  }
  return corrected;
}

// The exact finish (provot.hpp). Returns true when no spring is over the limit (with tolerance).
template <int D> bool projectExactly(const Network<D>& network, double max_strain, double tolerance, State<D>& s) {
  constexpr int kNewtonSteps = 20;
  std::vector<int> active;
  std::vector<Vec<D>> u;
  std::vector<double> c;
  std::vector<std::vector<std::pair<int, double>>> at(network.particleCount());  // (active index, sign)
  for (int step = 0;; ++step) {
    active.clear();
    u.clear();
    c.clear();
    bool over = false;
    for (int e = 0; e < network.springCount(); ++e) {
      const int a = network.spring_a[e], b = network.spring_b[e];
      if (network.pinned[a] && network.pinned[b]) continue;
      const Vec<D> l = s.x_m.col(a) - s.x_m.col(b);
      const double len = l.norm(), max_len = (1.0 + max_strain) * network.rest_length_m[e];
      over = over || len > max_len * (1.0 + tolerance);
      if (len < max_len * (1.0 - 1e-6)) continue;
      active.push_back(e);
      u.push_back(l / len);
      c.push_back(len - max_len);
    }
    if (!over) return true;
    if (step == kNewtonSteps) return false;
    for (auto& list : at) list.clear();
    for (int i = 0; i < int(active.size()); ++i) {
      const int a = network.spring_a[active[i]], b = network.spring_b[active[i]];
      if (!network.pinned[a]) at[a].push_back({i, 1.0});
      if (!network.pinned[b]) at[b].push_back({i, -1.0});
    }
    // (J W J^T)_ij = sum over free particles p shared by i and j of s_ip s_jp u_i . u_j.
    std::vector<Eigen::Triplet<double>> entries;
    for (const auto& list : at)
      for (const auto& [i, si] : list)
        for (const auto& [j, sj] : list) entries.emplace_back(i, j, si * sj * u[i].dot(u[j]));
    const int m = int(active.size());
    Eigen::SparseMatrix<double> A(m, m);
    A.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
    if (ldlt.info() != Eigen::Success) return false;
    const Eigen::VectorXd mu = ldlt.solve(-Eigen::Map<const Eigen::VectorXd>(c.data(), m));
    if (ldlt.info() != Eigen::Success || !mu.allFinite()) return false;
    for (int p = 0; p < network.particleCount(); ++p)
      for (const auto& [i, si] : at[p]) s.x_m.col(p) += si * mu[i] * u[i];
  }
}

}  // namespace

template <int D>
ProvotResult applyProvot(const Network<D>& network, const ProvotOptions& options, State<D>& s,
                         const Points<D>* step_start_x_m, double dt_s) {
  ProvotResult r;
  if (!options.enabled) return r;
  const bool set_velocity = step_start_x_m != nullptr && dt_s > 0;
  const Points<D> before = set_velocity ? s.x_m : Points<D>();
  r.converged = false;
  double worst = 0;
  while (r.passes < options.passes) {
    const long corrected = sweep(network, options.max_strain, options.tolerance, s, worst);
    ++r.passes;
    r.corrections += corrected;
    if (corrected == 0) {  // this sweep measured every spring within the limit and moved nothing
      r.converged = true;
      break;
    }
  }
  if (!r.converged && options.exact_finish) {
    r.finished_exactly = true;
    r.converged = projectExactly(network, options.max_strain, options.tolerance, s);
  }
  r.max_strain = r.converged && !r.finished_exactly ? worst : maxStrain(network, s);
  if (set_velocity && r.corrections > 0) {
    for (int p = 0; p < network.particleCount(); ++p)
      if (s.x_m.col(p) != before.col(p)) s.v_m_per_s.col(p) = (s.x_m.col(p) - step_start_x_m->col(p)) / dt_s;
  }
  return r;
}

template <int D> double maxStrain(const Network<D>& network, const State<D>& s) {
  double worst = 0;
  for (int e = 0; e < network.springCount(); ++e) {
    const double len = (s.x_m.col(network.spring_a[e]) - s.x_m.col(network.spring_b[e])).norm();
    const double strain = (len - network.rest_length_m[e]) / network.rest_length_m[e];
    worst = e == 0 ? strain : std::max(worst, strain);
  }
  return worst;
}

template ProvotResult applyProvot<2>(const Network<2>&, const ProvotOptions&, State<2>&, const Points<2>*, double);
template ProvotResult applyProvot<3>(const Network<3>&, const ProvotOptions&, State<3>&, const Points<3>*, double);
template double maxStrain<2>(const Network<2>&, const State<2>&);
template double maxStrain<3>(const Network<3>&, const State<3>&);

}  // namespace creaturelab::springs
