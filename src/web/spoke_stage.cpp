#include "web/spoke_stage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "core/rng.hpp"

namespace creaturelab::web {
namespace {

constexpr auto kHubAttachPurpose = core::purposeId("web.secondary_spoke_hub");

double angleAbout(const Point2& centre, const Point2& x) { return std::atan2(x.y() - centre.y(), x.x() - centre.x()); }

// Smallest angle between two directions given by their angles, in [0, pi].
double angularGap(double a, double b) { return std::fabs(std::remainder(a - b, 2 * std::numbers::pi)); }

}  // namespace

namespace {

// The best mass of the other segments under one rule, or -1 (see PrimarySpokeEnd).
int endOnFrame(const WebBuilder& web, const FrameLayout& frame, const std::vector<int>& segment,
               const Point2& from_m, PrimarySpokeEnd rule) {
  const Point2 ray = (frame.centre_m - from_m).normalized();
  const double to_centre = (frame.centre_m - from_m).norm();
  int best = -1;
  double best_score = 0;
  for (int p : frame.chain) {  // ties: first in frame order
    if (std::find(segment.begin(), segment.end(), p) != segment.end()) continue;
    const Point2 d = web.position(p) - from_m;
    double score = 0;
    if (rule == PrimarySpokeEnd::opposite) {
      if (d.dot(ray) <= to_centre) continue;  // not beyond the centre
      score = -std::fabs(cross2(ray, d));     // nearest the ray
    } else {
      score = d.norm();
    }
    if (best < 0 || score > best_score) best = p, best_score = score;
  }
  return best;
}

}  // namespace

int primarySpokeEnd(const WebBuilder& web, const FrameLayout& frame, const std::vector<int>& segment,
                    const Point2& from_m) {
  const int end = endOnFrame(web, frame, segment, from_m, web.params().primary_spoke_end);
  // Nothing beyond the centre cannot happen on a validated frame (the centre is inside the inner
  // frame); fall back to the literal rule rather than fail.
  return end >= 0 ? end : endOnFrame(web, frame, segment, from_m, PrimarySpokeEnd::farthest);
}

std::vector<std::vector<int>> layPrimarySpokes(WebBuilder& web, const FrameLayout& frame) {
  const int n = static_cast<int>(frame.segments.size());
  std::vector<std::vector<int>> primary;
  std::vector<Point2> directions;
  for (int j = 0; j < n; ++j) {
    const auto& seg = frame.segments[j];
    const int middle = seg[(seg.size() - 1) / 2];  // segment of m springs: mass m/2 (m >= 2 by validate)
    const Point2 xm = web.position(middle);
    const int far_end = primarySpokeEnd(web, frame, seg, xm);
    const Point2 u = (web.position(far_end) - xm).normalized();
    const bool repeats = std::any_of(directions.begin(), directions.end(), [&](const Point2& v) {
      return std::acos(std::min(1.0, std::fabs(u.dot(v)))) < web.params().primary_spoke_min_angle_rad;
    });
    if (repeats) continue;
    directions.push_back(u);
    primary.push_back(web.layStrand(middle, far_end, StrandType::primary_spoke));
  }
  return primary;
}

Point2 primaryIntersection(const WebBuilder& web, const FrameLayout& frame,
                           const std::vector<std::vector<int>>& primary) {
  std::vector<Point2> a, b;
  for (const auto& s : primary) {
    a.push_back(web.position(s.front()));
    b.push_back(web.position(s.back()));
  }
  const Point2 x = leastSquaresIntersection(a, b);
  std::vector<Point2> inner;
  for (int c : frame.corners) inner.push_back(web.position(c));
  return pointInPolygon(x, inner) ? x : frame.centre_m;
}

void joinHub(WebBuilder& web, SpokeLayout& spokes) {
  const Point2 c = spokes.hub_centre_m;
  const double r_hub = web.params().hub_radius_m;
  struct Arm {
    std::vector<int> masses;  // frame end first, up to and including the ring mass
    double angle;
  };
  std::vector<Arm> arms;
  for (const auto& strand : spokes.primary) {
    // Split at the mass nearest the intersection.
    size_t mid = 0;
    for (size_t i = 1; i < strand.size(); ++i)
      if ((web.position(strand[i]) - c).norm() < (web.position(strand[mid]) - c).norm()) mid = i;
    std::vector<int> first(strand.begin(), strand.begin() + mid + 1);
    std::vector<int> second(strand.rbegin(), strand.rend() - mid);
    for (auto* arm : {&first, &second}) {
      if (arm->size() < 2) continue;  // a spoke ending at the intersection has one arm only
      size_t ring = 0;
      for (size_t i = 1; i < arm->size(); ++i)
        if (std::fabs((web.position((*arm)[i]) - c).norm() - r_hub) <
            std::fabs((web.position((*arm)[ring]) - c).norm() - r_hub))
          ring = i;
      if (ring == 0) ring = 1;  // keep the frame end off the hub
      arm->resize(ring + 1);
      arms.push_back({*arm, angleAbout(c, web.position(arm->back()))});
    }
  }
  std::stable_sort(arms.begin(), arms.end(), [](const Arm& x, const Arm& y) { return x.angle < y.angle; });
  for (const auto& arm : arms) {
    spokes.hub.push_back(arm.masses.back());
    spokes.radii.push_back(arm.masses);
  }
  // The ring: consecutive arms' hub masses, closed (two arms: one strand).
  const int ring_count = static_cast<int>(arms.size());
  const int strands = ring_count > 2 ? ring_count : ring_count - 1;
  for (int i = 0; i < strands; ++i) {
    const int a = arms[i].masses.back(), b = arms[(i + 1) % ring_count].masses.back();
    if (a == b || (web.position(a) - web.position(b)).norm() <= 0) continue;
    const auto chain = web.layStrand(a, b, StrandType::hub);
    spokes.hub.insert(spokes.hub.end(), chain.begin() + 1, chain.end() - 1);
  }
}

void laySecondarySpokes(WebBuilder& web, const FrameLayout& frame, SpokeLayout& spokes) {
  const auto& prm = web.params();
  const Point2 c = spokes.hub_centre_m;
  std::vector<double> angles;
  for (const auto& r : spokes.radii) angles.push_back(angleAbout(c, web.position(r.front())));
  std::vector<char> ends_primary(web.particleCount(), 0);
  for (const auto& s : spokes.primary) ends_primary[s.front()] = ends_primary[s.back()] = 1;

  if (spokes.hub.empty()) return;
  const int n_chain = static_cast<int>(frame.chain.size());
  std::vector<int> order(spokes.hub.size());
  for (int i = 0; i < n_chain; i += prm.secondary_spoke_stride) {
    const int p = frame.chain[i];
    if (ends_primary[p]) continue;
    const Point2 xp = web.position(p);
    const double angle = angleAbout(c, xp);
    if (std::any_of(angles.begin(), angles.end(),
                    [&](double a) { return angularGap(a, angle) < prm.secondary_spoke_min_angle_rad; }))
      continue;
    // Hub masses by distance from p (ties: hub order); those whose spoke would cross a radius already
    // laid are dropped (a crossing puts two radii on top of each other and the spiral between them
    // would get strands of almost no length), unless all would cross.
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
      return (web.position(spokes.hub[x]) - xp).norm() < (web.position(spokes.hub[y]) - xp).norm();
    });
    std::vector<int> clear;
    for (int h : order) {
      if (static_cast<int>(clear.size()) == prm.hub_attach_choices) break;
      const int hub_mass = spokes.hub[h];
      const bool crosses = std::any_of(spokes.radii.begin(), spokes.radii.end(), [&](const std::vector<int>& r) {
        if (r.back() == hub_mass) return false;  // sharing the hub mass is not crossing
        return segmentsIntersect(xp, web.position(hub_mass), web.position(r.front()), web.position(r.back()));
      });
      if (!crosses) clear.push_back(hub_mass);
    }
    if (clear.empty()) clear.push_back(spokes.hub[order.front()]);
    // One of them at random (§5.2: "connected randomly to the masses in the hub").
    const double u = core::uniform01(prm.seed, kHubAttachPurpose, static_cast<std::uint64_t>(i));
    const int choices = static_cast<int>(clear.size());
    const int pick = std::min(choices - 1, static_cast<int>(u * choices));
    spokes.radii.push_back(web.layStrand(p, clear[pick], StrandType::secondary_spoke));
    angles.push_back(angle);
  }
}

SpokeLayout laySpokesAndHub(WebBuilder& web, const FrameLayout& frame) {
  SpokeLayout s;
  s.primary = layPrimarySpokes(web, frame);
  s.hub_centre_m = primaryIntersection(web, frame, s.primary);
  joinHub(web, s);
  laySecondarySpokes(web, frame, s);
  // Radii in order of the angle of their frame end about the hub centre (ties: order laid).
  std::vector<double> angle;
  for (const auto& r : s.radii) angle.push_back(angleAbout(s.hub_centre_m, web.position(r.front())));
  std::vector<int> idx(s.radii.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) { return angle[a] < angle[b]; });
  std::vector<std::vector<int>> sorted;
  for (int i : idx) sorted.push_back(std::move(s.radii[i]));
  s.radii = std::move(sorted);
  return s;
}

}  // namespace creaturelab::web
