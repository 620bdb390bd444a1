#include "charlotte/segments.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace creaturelab::charlotte {

std::vector<Segment> spiralSegments(const springs::Network<3>& net, const std::vector<web::StrandType>& type) {
  const int np = net.particleCount(), ns = net.springCount();
  std::vector<std::vector<int>> incident(np);
  for (int s = 0; s < ns; ++s) {
    incident[net.spring_a[s]].push_back(s);
    incident[net.spring_b[s]].push_back(s);
  }
  auto interior = [&](int p) {
    const auto& in = incident[p];
    return !net.pinned[p] && in.size() == 2 && type[in[0]] == web::StrandType::spiral &&
           type[in[1]] == web::StrandType::spiral;
  };
  std::vector<char> seen(ns, 0);
  std::vector<Segment> out;
  for (int s0 = 0; s0 < ns; ++s0) {
    if (type[s0] != web::StrandType::spiral || seen[s0]) continue;
    // Walk from s0 to both ends through interior masses; collect the chain in order a -> b.
    auto walk = [&](int from_spring, int through) {
      std::vector<std::pair<int, int>> steps;  // (spring, mass reached)
      int s = from_spring, p = through;
      while (interior(p)) {
        const auto& in = incident[p];
        const int next = in[0] == s ? in[1] : in[0];
        const int q = net.spring_a[next] == p ? net.spring_b[next] : net.spring_a[next];
        steps.push_back({next, q});
        s = next, p = q;
        if (steps.size() > std::size_t(ns)) throw std::logic_error("spiralSegments: a closed loop of spiral springs");
      }
      return std::make_pair(steps, p);
    };
    const auto [back, a_end] = walk(s0, net.spring_a[s0]);
    const auto [fwd, b_end] = walk(s0, net.spring_b[s0]);
    // Order a -> b: the backward walk reversed, s0, the forward walk. Interior masses likewise (the
    // last mass of each walk is the segment's end, not interior).
    Segment seg;
    seg.a = a_end, seg.b = b_end;
    for (std::size_t k = back.size(); k-- > 0;) {
      seg.springs.push_back(back[k].first);
    }
    seg.springs.push_back(s0);
    for (const auto& st : fwd) seg.springs.push_back(st.first);
    for (std::size_t k = back.size(); k-- > 0;)
      if (k + 1 < back.size()) seg.interior.push_back(back[k].second);
    if (!back.empty()) seg.interior.push_back(net.spring_a[s0]);
    if (!fwd.empty()) seg.interior.push_back(net.spring_b[s0]);
    for (std::size_t k = 0; k + 1 < fwd.size(); ++k) seg.interior.push_back(fwd[k].second);
    for (int s : seg.springs) seen[s] = 1;
    // As laid (layStrand numbers the springs from a to b): the lowest-numbered spring is at a.
    if (seg.springs.back() < seg.springs.front()) {
      std::reverse(seg.springs.begin(), seg.springs.end());
      std::reverse(seg.interior.begin(), seg.interior.end());
      std::swap(seg.a, seg.b);
    }
    out.push_back(std::move(seg));
  }
  return out;
}

Segment layStrand(springs::Network<3>& net, springs::State<3>& s, std::vector<web::StrandType>& type, int a, int b,
                  const web::StrandSpec& spec, web::StrandType strand_type, double mass_kg, SegmentOrigin origin) {
  const Eigen::Vector3d xa = s.x_m.col(a), xb = s.x_m.col(b);
  const double d = (xb - xa).norm();
  if (!(d > 0)) throw std::logic_error("charlotte: a strand between two masses at the same point");
  const long n = std::max(1L, std::lround(d / spec.placement_m));
  const double rest = spec.rest_over_laid * d / double(n);
  Segment seg;
  seg.a = a, seg.b = b, seg.origin = origin;
  const int first_new = net.particleCount();
  s.x_m.conservativeResize(Eigen::NoChange, first_new + n - 1);
  s.v_m_per_s.conservativeResize(Eigen::NoChange, first_new + n - 1);
  std::vector<int> chain{a};
  for (long i = 1; i < n; ++i) {
    const int p = net.addParticle(mass_kg, false);
    s.x_m.col(p) = xa + (xb - xa) * (double(i) / double(n));
    s.v_m_per_s.col(p).setZero();
    chain.push_back(p);
    seg.interior.push_back(p);
  }
  chain.push_back(b);
  for (long i = 0; i < n; ++i) {
    seg.springs.push_back(net.addSpring(chain[i], chain[i + 1], rest, spec.k_n_per_m, 0.0));
    type.push_back(strand_type);
  }
  return seg;
}

Pruned removeSprings(const springs::Network<3>& net, const springs::State<3>& s, const std::vector<web::StrandType>& type,
                     const std::vector<int>& springs_to_remove) {
  if (net.bendCount() > 0) throw std::logic_error("removeSprings: networks with bends are not supported (webs have none)");
  const int np = net.particleCount(), ns = net.springCount();
  std::vector<char> gone(ns, 0);
  for (int k : springs_to_remove) {
    if (k < 0 || k >= ns) throw std::out_of_range("removeSprings: spring " + std::to_string(k) + " does not exist");
    gone[k] = 1;
  }
  std::vector<int> degree(np, 0);
  for (int k = 0; k < ns; ++k)
    if (!gone[k]) ++degree[net.spring_a[k]], ++degree[net.spring_b[k]];
  Pruned out;
  out.new_particle.assign(np, -1);
  auto& o = out.network;
  o.gravity_m_per_s2 = net.gravity_m_per_s2;
  o.drag_ns_per_m = net.drag_ns_per_m;
  for (int p = 0; p < np; ++p) {
    if (degree[p] == 0 && !net.pinned[p]) {
      ++out.dropped_particles;
      continue;
    }
    out.new_particle[p] = int(out.particle_of.size());
    out.particle_of.push_back(p);
  }
  const int kept = int(out.particle_of.size());
  o.mass_kg.resize(kept);
  out.state.x_m.resize(3, kept);
  out.state.v_m_per_s.resize(3, kept);
  for (int i = 0; i < kept; ++i) {
    const int p = out.particle_of[i];
    o.mass_kg[i] = net.mass_kg[p];
    o.pinned.push_back(net.pinned[p]);
    out.state.x_m.col(i) = s.x_m.col(p);
    out.state.v_m_per_s.col(i) = s.v_m_per_s.col(p);
  }
  for (int k = 0; k < ns; ++k) {
    if (gone[k]) continue;
    o.addSpring(out.new_particle[net.spring_a[k]], out.new_particle[net.spring_b[k]], net.rest_length_m[k],
                net.stiffness_n_per_m[k], net.damping_ns_per_m[k]);
    out.type.push_back(type[k]);
    out.spring_of.push_back(k);
  }
  return out;
}

}  // namespace creaturelab::charlotte
