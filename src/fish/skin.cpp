#include "fish/skin.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace creaturelab::fish {

std::string SkinParams::validate() const {
  const SkinParams& p = *this;
  if (p.degree_around < 1 || p.degree_around >= kSkinAround)
    return "skin_degree_around " + std::to_string(p.degree_around) + " must be in [1, " + std::to_string(kSkinAround - 1) +
           "]: a NURBS degree needs more control points than itself (" + std::to_string(kSkinAround) + " around)";
  if (p.degree_along < 1 || p.degree_along >= kSkinAlong)
    return "skin_degree_along " + std::to_string(p.degree_along) + " must be in [1, " + std::to_string(kSkinAlong - 1) +
           "]: a NURBS degree needs more control points than itself (" + std::to_string(kSkinAlong) + " along)";
  if (!(p.inflate > 0) || !std::isfinite(p.inflate)) return "skin_inflate must be positive";
  if (!(std::fabs(p.pectoral_pitch_deg) <= 90)) return "pectoral_pitch_deg must be in [-90, 90]";
  return "";
}

Eigen::Vector3d FishSkin::patchNode(const NodeMatrix& x, const Face& f, int s4, int t4) {
  // Seed: "define each face as a parametric bilinear surface with parameters s and t".
  const double s = 0.25 * s4, t = 0.25 * t4;
  return ((1 - s) * (1 - t) * x.row(f.node[0]) + s * (1 - t) * x.row(f.node[1]) + s * t * x.row(f.node[2]) +
          (1 - s) * t * x.row(f.node[3]))
      .transpose();
}

Eigen::Matrix3d FishSkin::faceFrame(const NodeMatrix& x, const Face& f) {
  // Seed: "the u-axis is the normal of the surface and one of the edges of the face is the v-axis".
  const Eigen::Vector3d u = faceNormal(x, f).normal;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {  // the first non-zero edge (a triangle repeats a vertex)
    Eigen::Vector3d e = (x.row(f.node[(k + 1) % 4]) - x.row(f.node[k])).transpose();
    e -= e.dot(u) * u;
    if (e.norm() > 0) {
      v = e.normalized();
      break;
    }
  }
  Eigen::Matrix3d frame;
  frame.col(0) = u;
  frame.col(1) = v;
  frame.col(2) = u.cross(v);
  return frame;
}

namespace {

// Piecewise-linear section half-sizes along the body (fractions of the body length), at station s.
struct Section {
  double half_width, half_height;
};
Section sectionAt(const FishGeometry& g, double s) {
  std::vector<double> st = {0.0}, hw = {0.0}, hh = {0.0};
  for (int r = 0; r < 5; ++r) st.push_back(g.ring_station[r]), hw.push_back(g.ring_half_width[r]), hh.push_back(g.ring_half_height[r]);
  st.push_back(1.0), hw.push_back(0.0), hh.push_back(g.tail_half_height);
  for (size_t k = 1; k < st.size(); ++k)
    if (s <= st[k]) {
      const double a = (s - st[k - 1]) / (st[k] - st[k - 1]);
      return {(1 - a) * hw[k - 1] + a * hw[k], (1 - a) * hh[k - 1] + a * hh[k]};
    }
  return {0.0, g.tail_half_height};
}

// The undeformed control net of one half: side +1 left (y > 0), -1 right. Around index i from the
// dorsal midline (i = 0) down the side to the ventral midline (i = 8); along index j snout to tail.
std::vector<Eigen::Vector3d> halfNet(const FishModel& fish, const SkinParams& p, int side) {
  // The body's section sizes, read back from the undeformed nodes (rings 1-5 and the tail tips).
  FishGeometry g;
  const NodeMatrix& x = fish.rest_positions_m;
  const double L = fish.body_length_m;
  for (int r = 0; r < 5; ++r) {
    g.ring_station[r] = -x(1 + 4 * r, 0) / L;
    g.ring_half_width[r] = x(1 + 4 * r, 1) / L;
    g.ring_half_height[r] = x(1 + 4 * r, 2) / L;
  }
  g.tail_half_height = x(21, 2) / L;
  std::vector<Eigen::Vector3d> net(kSkinAround * kSkinAlong);
  for (int i = 0; i < kSkinAround; ++i) {
    const double theta = M_PI / 2 - M_PI * i / (kSkinAround - 1);
    for (int j = 0; j < kSkinAlong; ++j) {
      const double s = double(j) / (kSkinAlong - 1);
      const Section sec = sectionAt(g, s);
      // The midlines (i = 0, 8) lie exactly in the plane y = 0: cos(pi/2) is not 0 in floating point.
      const double c = (i == 0 || i == kSkinAround - 1) ? 0.0 : std::cos(theta);
      net[i * kSkinAlong + j] = Eigen::Vector3d(-s * L, side * p.inflate * sec.half_width * L * c,
                                                p.inflate * sec.half_height * L * std::sin(theta));
    }
  }
  return net;
}

NurbsSurface surfaceOf(int count_u, int count_v, int degree_u, int degree_v) {
  NurbsSurface s;
  s.count_u = count_u, s.count_v = count_v, s.degree_u = degree_u, s.degree_v = degree_v;
  s.knots_u = clampedUniformKnots(count_u, degree_u);
  s.knots_v = clampedUniformKnots(count_v, degree_v);
  s.control.assign(size_t(count_u) * count_v, Eigen::Vector4d(0, 0, 0, 1));
  return s;
}

}  // namespace

FishSkin::FishSkin(const FishModel& fish, SkinParams params) : fish_(fish), params_(params) {
  if (auto m = params_.validate(); !m.empty()) throw std::invalid_argument(m);
  const NodeMatrix& x = fish.rest_positions_m;
  for (int side : {+1, -1}) {
    const auto net = halfNet(fish, params_, side);
    rest_control_.insert(rest_control_.end(), net.begin(), net.end());
    surfaces_.push_back(surfaceOf(kSkinAround, kSkinAlong, params_.degree_around, params_.degree_along));
  }
  if (params_.fins) {
    // Dorsal fin over stations j = 6..10 of the dorsal midline, ventral fin under j = 11..15 of the
    // ventral midline: base row = those midline control points, then two rows raised (ours: a fin
    // 0.07 L high at its middle, swept back).
    const double L = fish.body_length_m;
    for (int fin = 0; fin < 2; ++fin) {
      const int i_mid = fin == 0 ? 0 : kSkinAround - 1, j0 = fin == 0 ? 6 : 11;
      const double up = fin == 0 ? 1.0 : -1.0;
      const double height[5] = {0.0, 0.8, 1.0, 0.6, 0.0};
      for (int row = 0; row < 3; ++row)
        for (int k = 0; k < 5; ++k) {
          Eigen::Vector3d base = rest_control_[i_mid * kSkinAlong + j0 + k];
          base += Eigen::Vector3d(-0.03 * L * row, 0.0, up * 0.035 * L * row * height[k]);
          rest_control_.push_back(base);
        }
      surfaces_.push_back(surfaceOf(3, 5, 2, 3));
    }
  }
  // Set-up (seed, steps 1-3): patch-nodes and frames of the undeformed model, nearest patch-node,
  // offset in the face's frame.
  for (int f = 0; f < kFaces; ++f) frames_[f] = faceFrame(x, fish.faces[f]);
  // A control point off the midplane binds only to faces on its own side or on the midplane
  // (ours): bound to a face of the other side, a point near the thin tail would be carried across
  // the midplane when the tail bends, folding the skin over (found by the fold-over test).
  std::array<double, kFaces> face_y{};
  for (int f = 0; f < kFaces; ++f) {
    for (int k : fish.faces[f].node) face_y[f] += x(k, 1) / 4;
  }
  const double midplane = 1e-12 * fish.body_length_m;
  bindings_.resize(rest_control_.size());
  for (size_t c = 0; c < rest_control_.size(); ++c) {
    double best = std::numeric_limits<double>::infinity();
    SkinBinding b;
    const double y = rest_control_[c].y();
    for (int f = 0; f < kFaces; ++f) {
      if ((y > midplane && face_y[f] < -midplane) || (y < -midplane && face_y[f] > midplane)) continue;
      for (int s = 0; s <= 4; ++s)
        for (int t = 0; t <= 4; ++t) {
          const double d = (patchNode(x, fish.faces[f], s, t) - rest_control_[c]).squaredNorm();
          if (d < best) best = d, b.face = f, b.s = s, b.t = t;
        }
    }
    b.offset = frames_[b.face].transpose() * (rest_control_[c] - patchNode(x, fish.faces[b.face], b.s, b.t));
    bindings_[c] = b;
  }
  // Fins share their base row with the midlines: bind them to exactly the same patch-node and offset.
  if (params_.fins) {
    const size_t first_fin = 2 * kSkinAround * kSkinAlong;
    for (int fin = 0; fin < 2; ++fin) {
      const int i_mid = fin == 0 ? 0 : kSkinAround - 1, j0 = fin == 0 ? 6 : 11;
      for (int k = 0; k < 5; ++k) bindings_[first_fin + fin * 15 + k] = bindings_[i_mid * kSkinAlong + j0 + k];
    }
  }
  update(x);
}

void FishSkin::update(const NodeMatrix& x) {
  nodes_ = x;
  // Each display step (seed, step 4): frames, patch-nodes, offsets back to world coordinates.
  for (int f = 0; f < kFaces; ++f) frames_[f] = faceFrame(x, fish_.faces[f]);
  size_t c = 0;
  for (NurbsSurface& s : surfaces_)
    for (auto& point : s.control) {
      const SkinBinding& b = bindings_[c++];
      const Eigen::Vector3d p = patchNode(x, fish_.faces[b.face], b.s, b.t) + frames_[b.face] * b.offset;
      point << p, 1.0;
    }
}

std::vector<Eigen::Vector3d> FishSkin::controlPoints() const {
  std::vector<Eigen::Vector3d> out;
  for (const NurbsSurface& s : surfaces_)
    for (const auto& h : s.control) out.push_back(h.head<3>() / h[3]);
  return out;
}

void FishSkin::mesh(int around, int along, SkinMesh& out) {
  if (around != cached_around_ || along != cached_along_) {
    basis_u_.clear(), basis_v_.clear();
    for (const NurbsSurface& s : surfaces_) {
      const bool body = &s - surfaces_.data() < 2;
      basis_u_.push_back(sampleBasis(s.count_u, s.degree_u, s.knots_u, body ? around : 4));
      basis_v_.push_back(sampleBasis(s.count_v, s.degree_v, s.knots_v, body ? along : 8));
    }
    cached_around_ = around, cached_along_ = along;
  }
  out.positions.clear();
  out.triangles.clear();
  out.samples_around = around, out.samples_along = along;
  for (size_t k = 0; k < surfaces_.size(); ++k) {
    evaluateGrid(surfaces_[k], basis_u_[k], basis_v_[k], grid_, scratch_);
    const int nu = int(basis_u_[k].span.size()), nv = int(basis_v_[k].span.size());
    const int base = int(out.positions.size());
    out.positions.insert(out.positions.end(), grid_.begin(), grid_.end());
    // Left half: d/du points down, d/dv backwards, (du x dv) = +y, outward; the right half (and the
    // ventral fin) is mirrored, so its winding is reversed.
    const bool flip = k == 1 || k == 3;
    for (int iu = 0; iu + 1 < nu; ++iu)
      for (int iv = 0; iv + 1 < nv; ++iv) {
        const int a = base + iu * nv + iv, b = a + nv, c = b + 1, d = a + 1;
        if (flip) {
          out.triangles.push_back({a, c, b});
          out.triangles.push_back({a, d, c});
        } else {
          out.triangles.push_back({a, b, c});
          out.triangles.push_back({a, c, d});
        }
      }
    if (k == 1) out.body_triangles = int(out.triangles.size());
  }
  if (params_.pectoral_fins) {
    const auto fins = pectoralFins(nodes_);
    for (int side = 0; side < 2; ++side) {
      const int base = int(out.positions.size());
      out.positions.insert(out.positions.end(), fins.begin() + 5 * side, fins.begin() + 5 * side + 5);
      for (int k = 1; k <= 3; ++k)  // a fan from the root's front vertex; the right fin mirrored
        out.triangles.push_back(side == 0 ? std::array<int, 3>{base, base + k + 1, base + k}
                                          : std::array<int, 3>{base, base + k, base + k + 1});
    }
  }
  // Vertex normals: area-weighted sums of the triangles' normals (the cross product's length is
  // twice the area), normalised.
  out.normals.assign(out.positions.size(), Eigen::Vector3d::Zero());
  for (const auto& t : out.triangles) {
    const Eigen::Vector3d n = (out.positions[t[1]] - out.positions[t[0]]).cross(out.positions[t[2]] - out.positions[t[0]]);
    for (int v : t) out.normals[v] += n;
  }
  for (auto& n : out.normals) {
    const double len = n.norm();
    n = len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d(0, 0, 1);
  }
}

FoldCheck checkOutward(const SkinMesh& m) {
  FoldCheck out;
  const int nu = m.samples_around, nv = m.samples_along;
  auto sample = [&](int half, int iu, int iv) -> const Eigen::Vector3d& { return m.positions[(half * nu + iu) * nv + iv]; };
  // Each station's section: centre (mean of both halves' samples), a frame (axis along the body from
  // the neighbouring centres, "up" = z made orthogonal to it, lateral = up x axis) and the section's
  // half-extents a (lateral) and b (up). The outward direction at a point of the section is the
  // gradient of the ellipse (y/a)^2 + (z/b)^2 there, which stays right on the thin tail edge, where
  // the direction from the centre alone would point along the fin instead of across it.
  struct Station {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(), lateral, up;
    double a = 0, b = 0;
  };
  std::vector<Station> st(nv);
  for (int half = 0; half < 2; ++half)
    for (int iu = 0; iu < nu; ++iu)
      for (int iv = 0; iv < nv; ++iv) st[iv].centre += sample(half, iu, iv) / (2.0 * nu);
  for (int iv = 0; iv < nv; ++iv) {
    Eigen::Vector3d axis = st[std::min(iv + 1, nv - 1)].centre - st[std::max(iv - 1, 0)].centre;
    axis.normalize();
    st[iv].up = (Eigen::Vector3d::UnitZ() - axis.z() * axis).normalized();
    st[iv].lateral = st[iv].up.cross(axis);
    for (int half = 0; half < 2; ++half)
      for (int iu = 0; iu < nu; ++iu) {
        const Eigen::Vector3d d = sample(half, iu, iv) - st[iv].centre;
        st[iv].a = std::max(st[iv].a, std::fabs(d.dot(st[iv].lateral)));
        st[iv].b = std::max(st[iv].b, std::fabs(d.dot(st[iv].up)));
      }
  }
  double largest = 0, extent = 0;
  for (const auto& s : st) extent = std::max({extent, s.a, s.b});
  for (int k = 0; k < m.body_triangles; ++k) {
    const auto& t = m.triangles[k];
    largest = std::max(largest, (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm());
  }
  for (int k = 0; k < m.body_triangles; ++k) {
    const auto& t = m.triangles[k];
    const Eigen::Vector3d n = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    if (n.norm() <= 1e-12 * largest) continue;  // degenerate (the snout's pole)
    // The section at the triangle: its vertices' stations averaged (a triangle spans two stations,
    // and near the thin tail the midline moves sideways between them by more than the fin is thick).
    Station s;
    s.lateral = s.up = Eigen::Vector3d::Zero();
    for (int v : t) {
      const Station& sv = st[(v % (nu * nv)) % nv];
      s.centre += sv.centre / 3.0, s.lateral += sv.lateral / 3.0, s.up += sv.up / 3.0;
      s.a += sv.a / 3.0, s.b += sv.b / 3.0;
    }
    if (s.a <= 1e-9 * extent && s.b <= 1e-9 * extent) continue;
    const Eigen::Vector3d d = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0 - s.centre;
    const double a2 = std::max(s.a * s.a, 1e-18), b2 = std::max(s.b * s.b, 1e-18);
    const Eigen::Vector3d outward = d.dot(s.lateral) / a2 * s.lateral + d.dot(s.up) / b2 * s.up;
    if (outward.norm() == 0) continue;
    const double cosine = n.normalized().dot(outward.normalized());
    ++out.checked;
    // Edge-on triangles (cosine 0 up to round-off: the zero-width tail edge lies in the midplane,
    // its normal across the fin and the section's outward direction along it) are not folded.
    if (cosine < -1e-9) ++out.inward;
    if (cosine < out.worst_cosine) out.worst_cosine = cosine, out.worst_triangle = k;
  }
  // Creases: the two triangles of a grid cell, and each with the triangles of the next cells
  // around and along (the mesh writes two triangles per cell, cell by cell, see FishSkin::mesh).
  auto unit = [&](int k) -> Eigen::Vector3d {
    const auto& t = m.triangles[k];
    const Eigen::Vector3d n = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    return n.norm() > 1e-12 * largest ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
  };
  const int cells_v = nv - 1;
  for (int half = 0; half < 2; ++half)
    for (int iu = 0; iu + 1 < nu; ++iu)
      for (int iv = 0; iv < cells_v; ++iv) {
        const int cell = (half * (nu - 1) + iu) * cells_v + iv;
        const Eigen::Vector3d a = unit(2 * cell), b = unit(2 * cell + 1);
        std::vector<Eigen::Vector3d> others = {b};
        if (iv + 1 < cells_v) others.push_back(unit(2 * (cell + 1)));
        if (iu + 2 < nu) others.push_back(unit(2 * (cell + cells_v) + 1));
        for (const auto& o : others) {
          const double c = a.dot(o);
          if (a.norm() == 0 || o.norm() == 0) continue;
          if (c < 0) ++out.creases;
          out.worst_neighbour_cosine = std::min(out.worst_neighbour_cosine, c);
        }
      }
  return out;
}

double seamGapM(const SkinMesh& m) {
  const int around = m.samples_around, along = m.samples_along, half = around * along;
  double gap = 0;
  for (int iv = 0; iv < along; ++iv)
    for (int iu : {0, around - 1}) gap = std::max(gap, (m.positions[iu * along + iv] - m.positions[half + iu * along + iv]).norm());
  for (int iu = 0; iu < around; ++iu)
    gap = std::max(gap, (m.positions[iu * along + along - 1] - m.positions[half + iu * along + along - 1]).norm());
  return gap;
}

std::array<Eigen::Vector3d, 10> FishSkin::pectoralFins(const NodeMatrix& x) const {
  // The fish frame from the nodes: forward from ring 2's centre to the snout, up from ring 1's lower
  // nodes to its upper ones (made orthogonal), left = up x forward (the body's +y at rest).
  auto node = [&](int i) -> Eigen::Vector3d { return x.row(i).transpose(); };
  const Eigen::Vector3d ring2 = (node(5) + node(6) + node(7) + node(8)) / 4.0;
  const Eigen::Vector3d forward = (node(0) - ring2).normalized();
  Eigen::Vector3d up = (node(1) + node(4) - node(2) - node(3)) / 2.0;
  up = (up - up.dot(forward) * forward).normalized();
  const Eigen::Vector3d left = up.cross(forward);
  const double L = fish_.body_length_m, pitch = params_.pectoral_pitch_deg * M_PI / 180.0;
  // Ours (no shape survives in text): a swept-back, rounded fin in body lengths (forward, out, down
  // from the root); 5 vertices: root front, root back, then around the tip from back to front.
  static constexpr double kFin[5][3] = {{0.03, 0.0, 0.0}, {-0.05, 0.0, 0.0}, {-0.13, 0.10, 0.03}, {-0.09, 0.13, 0.04}, {-0.02, 0.09, 0.02}};
  std::array<Eigen::Vector3d, 10> out;
  for (int side = 0; side < 2; ++side) {
    const double s = side == 0 ? 1.0 : -1.0;
    // Root on the lower flank, halfway between rings 1 and 2 (lower-left nodes 2, 6; lower-right 3, 7).
    const Eigen::Vector3d root = side == 0 ? (node(2) + node(6)) / 2.0 : (node(3) + node(7)) / 2.0;
    for (int k = 0; k < 5; ++k) {
      const double f = kFin[k][0] * L, o = kFin[k][1] * L, d = kFin[k][2] * L;
      // Pitch about the lateral axis through the root: the forward/down components turn together.
      const double fp = f * std::cos(pitch) - (-d) * std::sin(pitch), up_p = f * std::sin(pitch) + (-d) * std::cos(pitch);
      out[5 * side + k] = root + fp * forward + s * o * left + up_p * up;
    }
  }
  return out;
}

}  // namespace creaturelab::fish
