#include "sim/collision/narrow_phase.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/check.h"
#include "sim/collision/ccd.h"
#include "sim/collision/exact_distance.h"

namespace recoil::sim {
namespace {

Eigen::Vector3d row(const Points& x, int i) { return x.row(i).transpose(); }

// Distances below this count as touching (metres); relative to the scene's
// coordinates because that is where double rounding lives.
double pair_tolerance(const PreparedSurface& a, const PreparedSurface& b) {
  return 1e-10 * (1.0 + std::max(a.length_scale, b.length_scale));
}

// The rule in narrow_phase.h. sep0 = p0 - q0 (start of step, with the
// candidate's weights), rel = relative motion of p with respect to q over the
// step, feature = face normal / edge cross product where the contact is
// judged (zero if degenerate). `outward`: the feature's own sign means
// something (a face normal of a counter-clockwise triangle points out of B).
Eigen::Vector3d choose_normal(bool touching, const Eigen::Vector3d& sep0, Eigen::Vector3d feature, bool outward,
                              const Eigen::Vector3d& rel, double tol) {
  const double sep_norm = sep0.norm();
  if (!touching && sep_norm > 0.0) return sep0 / sep_norm;
  const double feature_norm = feature.norm();
  if (feature_norm > 0.0) {
    feature /= feature_norm;
    const double along = feature.dot(sep0);
    if (std::abs(along) > tol) return along > 0.0 ? feature : Eigen::Vector3d(-feature);
    // Touching at the start: which side p is on is unknown. Trust the
    // surface orientation if there is one (A outside B), else assume p
    // approaches along its relative motion.
    if (outward) return feature;
    return feature.dot(rel) > 0.0 ? Eigen::Vector3d(-feature) : feature;
  }
  if (sep_norm > tol) return sep0 / sep_norm;
  const double rel_norm = rel.norm();
  if (rel_norm > 0.0) return -rel / rel_norm;
  return Eigen::Vector3d::UnitZ();
}

// Face normal, or zero for a triangle whose normal is lost in rounding.
Eigen::Vector3d face_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double scale = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return n.squaredNorm() > 1e-24 * scale * scale ? n : Eigen::Vector3d::Zero();
}

Eigen::Vector3d edge_cross(const Eigen::Vector3d& da, const Eigen::Vector3d& db) {
  const Eigen::Vector3d n = da.cross(db);
  return n.squaredNorm() > 1e-24 * da.squaredNorm() * db.squaredNorm() ? n : Eigen::Vector3d::Zero();
}

Eigen::Vector3d lerp(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, double s) { return x0 + s * (x1 - x0); }

// Barycentric weights below this are rounding noise of a closest point that
// lies on an edge or vertex (a vertex above a triangulation diagonal): they
// are set to zero so that both triangles name the same feature.
constexpr double kFeatureWeightTolerance = 1e-9;

std::array<double, 3> snap_to_feature(std::array<double, 3> w) {
  double sum = 0.0;
  for (double& wi : w) {
    if (wi < kFeatureWeightTolerance) wi = 0.0;
    sum += wi;
  }
  for (double& wi : w) wi /= sum;
  return w;
}

bool on_triangle_boundary(const std::array<double, 3>& w) { return w[0] == 0.0 || w[1] == 0.0 || w[2] == 0.0; }

}  // namespace

std::vector<std::array<int, 2>> unique_edges(const Triangles& triangles) {
  std::vector<std::array<int, 2>> edges;
  edges.reserve(3 * static_cast<size_t>(triangles.rows()));
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = triangles(f, k), w = triangles(f, (k + 1) % 3);
      edges.push_back({std::min(v, w), std::max(v, w)});
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

PreparedSurface prepare_surface(const CollisionSurface& surface, int index,
                                const std::vector<std::array<int, 2>>* edges) {
  PreparedSurface out;
  out.surface = &surface;
  out.index = index;
  const int nv = static_cast<int>(surface.x0.rows());
  RECOIL_CHECK(surface.x1.rows() == nv, "surface " << index << ": x0 has " << nv << " rows, x1 " << surface.x1.rows());
  RECOIL_CHECK(surface.x0.allFinite() && surface.x1.allFinite(), "surface " << index << " has non-finite positions");
  out.vertex_motion.resize(static_cast<size_t>(nv));
  for (int v = 0; v < nv; ++v) {
    out.box0.extend(row(surface.x0, v));
    out.vertex_motion[v] = (row(surface.x1, v) - row(surface.x0, v)).norm();
    out.max_motion = std::max(out.max_motion, out.vertex_motion[v]);
  }
  if (nv > 0)
    out.length_scale = std::max(surface.x0.cwiseAbs().maxCoeff(), surface.x1.cwiseAbs().maxCoeff());
  const int nf = static_cast<int>(surface.triangles.rows());
  out.triangle_motion.resize(static_cast<size_t>(nf));
  for (int f = 0; f < nf; ++f) {
    double motion = 0.0;
    for (int k = 0; k < 3; ++k) {
      const int v = surface.triangles(f, k);
      RECOIL_CHECK(v >= 0 && v < nv, "surface " << index << " triangle " << f << " has vertex " << v);
      motion = std::max(motion, out.vertex_motion[v]);
    }
    out.triangle_motion[f] = motion;
  }
  out.edges = edges ? *edges : unique_edges(surface.triangles);
  out.edge_motion.resize(out.edges.size());
  for (size_t e = 0; e < out.edges.size(); ++e)
    out.edge_motion[e] = std::max(out.vertex_motion[out.edges[e][0]], out.vertex_motion[out.edges[e][1]]);
  return out;
}

bool boxes_may_interact(const PreparedSurface& a, const PreparedSurface& b, double margin) {
  if (!a.box0.valid() || !b.box0.valid()) return false;
  const double reach = margin + a.max_motion + b.max_motion;
  return ((a.box0.min - b.box0.max).array() <= reach).all() && ((b.box0.min - a.box0.max).array() <= reach).all();
}

bool surfaces_interact(const PreparedSurface& a, const PreparedSurface& b) {
  return !(is_prescribed(a.surface->kind) && is_prescribed(b.surface->kind));
}
bool self_interacts(const PreparedSurface& a) {
  return a.surface->kind == SurfaceKind::deformable && a.surface->self_contact;
}
bool interacts_with_planes(const PreparedSurface& a) { return !is_prescribed(a.surface->kind); }

std::optional<ContactCandidate> test_vertex_triangle(const PreparedSurface& a, int vertex, const PreparedSurface& b,
                                                     int triangle, double margin) {
  const CollisionSurface& sa = *a.surface;
  const CollisionSurface& sb = *b.surface;
  const std::array<int, 3> tv = {sb.triangles(triangle, 0), sb.triangles(triangle, 1), sb.triangles(triangle, 2)};
  if (a.index == b.index && (tv[0] == vertex || tv[1] == vertex || tv[2] == vertex)) return std::nullopt;

  const Eigen::Vector3d p0 = row(sa.x0, vertex), p1 = row(sa.x1, vertex);
  std::array<Eigen::Vector3d, 3> t0, t1;
  for (int k = 0; k < 3; ++k) {
    t0[k] = row(sb.x0, tv[k]);
    t1[k] = row(sb.x1, tv[k]);
  }
  const TriangleClosestPoint closest = closest_point_on_triangle(p0, t0[0], t0[1], t0[2]);
  const double distance = (p0 - closest.point).norm();
  const double motion = a.vertex_motion[vertex] + b.triangle_motion[triangle];
  if (!(distance <= margin + motion)) return std::nullopt;
  // The same bound from the end of the step (narrow_phase.h).
  if (motion > 0.0) {
    const Eigen::Vector3d end = closest_point_on_triangle(p1, t1[0], t1[1], t1[2]).point;
    if (!((p1 - end).norm() <= margin + motion)) return std::nullopt;
  }

  const double tol = pair_tolerance(a, b);
  ContactCandidate c;
  c.kind = ContactKind::vertex_triangle;
  c.surface_a = a.index;
  c.surface_b = b.index;
  c.body_a = sa.body;
  c.body_b = sb.body;
  c.primitive_a = vertex;
  c.primitive_b = triangle;
  c.a.count = 1;
  c.a.vertex = {vertex, -1, -1};
  c.a.weight = {1.0, 0.0, 0.0};
  c.b.count = 3;
  c.b.vertex = tv;
  // A root of the coplanarity cubic is known to ~1e-12 of the step at worst
  // (grazing motion), so the touch test allows that much of the motion too.
  if (motion > 0.0)
    c.toi = vertex_triangle_toi(p0, p1, t0[0], t1[0], t0[1], t1[1], t0[2], t1[2], tol + 1e-12 * motion);

  Eigen::Vector3d feature = Eigen::Vector3d::Zero();
  if (c.toi) {
    // Weights and normal where the vertex meets the triangle.
    const double s = *c.toi;
    const Eigen::Vector3d ta = lerp(t0[0], t1[0], s), tb = lerp(t0[1], t1[1], s), tc = lerp(t0[2], t1[2], s);
    c.b.weight = snap_to_feature(closest_point_on_triangle(lerp(p0, p1, s), ta, tb, tc).weight);
    feature = face_normal(ta, tb, tc);
  } else {
    c.b.weight = snap_to_feature(closest.weight);
    feature = face_normal(t0[0], t0[1], t0[2]);
  }
  const Eigen::Vector3d q0 = c.b.evaluate(sb.x0), q1 = c.b.evaluate(sb.x1);
  const Eigen::Vector3d sep0 = p0 - q0, rel = (p1 - q1) - sep0;
  const bool touching_at_start = sep0.norm() <= tol;
  // Touching at the start on an edge or vertex of this triangle: its face
  // normal is only one of the feature's normals (a corner resting exactly on
  // a corner touches the top face and both side faces). Only a face that the
  // vertex is moving into defines the contact; the others are left to the
  // neighbouring triangles of the same feature (narrow_phase.h).
  if (touching_at_start && on_triangle_boundary(c.b.weight) && !(feature.dot(rel) < 0.0)) return std::nullopt;
  const bool touching = c.toi.has_value() || touching_at_start;
  c.normal = choose_normal(touching, sep0, feature, /*outward=*/true, rel, tol);
  c.gap = c.normal.dot(sep0);
  return c;
}

std::optional<ContactCandidate> test_edge_edge(const PreparedSurface& a, int edge_a, const PreparedSurface& b,
                                               int edge_b, double margin) {
  const std::array<int, 2> ea = a.edges[edge_a], eb = b.edges[edge_b];
  if (a.index == b.index) {
    RECOIL_CHECK(edge_a < edge_b, "self edge pair " << edge_a << ", " << edge_b << " not ordered");
    if (ea[0] == eb[0] || ea[0] == eb[1] || ea[1] == eb[0] || ea[1] == eb[1]) return std::nullopt;
  }
  const CollisionSurface& sa = *a.surface;
  const CollisionSurface& sb = *b.surface;
  const Eigen::Vector3d a0 = row(sa.x0, ea[0]), a1 = row(sa.x0, ea[1]);
  const Eigen::Vector3d b0 = row(sb.x0, eb[0]), b1 = row(sb.x0, eb[1]);
  SegmentClosestPoints closest = closest_points_on_segments(a0, a1, b0, b1);
  const double distance = ((a0 + closest.s * (a1 - a0)) - (b0 + closest.t * (b1 - b0))).norm();
  const double motion = a.edge_motion[edge_a] + b.edge_motion[edge_b];
  if (!(distance <= margin + motion)) return std::nullopt;

  const double tol = pair_tolerance(a, b);
  const Eigen::Vector3d a0e = row(sa.x1, ea[0]), a1e = row(sa.x1, ea[1]);
  const Eigen::Vector3d b0e = row(sb.x1, eb[0]), b1e = row(sb.x1, eb[1]);
  if (motion > 0.0) {  // the same bound from the end of the step
    const SegmentClosestPoints end = closest_points_on_segments(a0e, a1e, b0e, b1e);
    if (!(((a0e + end.s * (a1e - a0e)) - (b0e + end.t * (b1e - b0e))).norm() <= margin + motion)) return std::nullopt;
  }
  std::optional<double> toi;
  if (motion > 0.0) toi = edge_edge_toi(a0, a0e, a1, a1e, b0, b0e, b1, b1e, tol + 1e-12 * motion);
  Eigen::Vector3d feature;
  if (toi) {
    const double s = *toi;
    const Eigen::Vector3d pa = lerp(a0, a0e, s), qa = lerp(a1, a1e, s), pb = lerp(b0, b0e, s), qb = lerp(b1, b1e, s);
    closest = closest_points_on_segments(pa, qa, pb, qb);
    feature = edge_cross(qa - pa, qb - pb);
  } else {
    feature = edge_cross(a1 - a0, b1 - b0);
  }
  // A closest point at an edge's end is a vertex contact (narrow_phase.h).
  if (closest.s == 0.0 || closest.s == 1.0 || closest.t == 0.0 || closest.t == 1.0) return std::nullopt;

  ContactCandidate c;
  c.kind = ContactKind::edge_edge;
  c.surface_a = a.index;
  c.surface_b = b.index;
  c.body_a = sa.body;
  c.body_b = sb.body;
  c.primitive_a = edge_a;
  c.primitive_b = edge_b;
  c.a.count = 2;
  c.a.vertex = {ea[0], ea[1], -1};
  c.a.weight = {1.0 - closest.s, closest.s, 0.0};
  c.b.count = 2;
  c.b.vertex = {eb[0], eb[1], -1};
  c.b.weight = {1.0 - closest.t, closest.t, 0.0};
  c.toi = toi;
  const Eigen::Vector3d sep0 = c.a.evaluate(sa.x0) - c.b.evaluate(sb.x0);
  const Eigen::Vector3d rel = (c.a.evaluate(sa.x1) - c.b.evaluate(sb.x1)) - sep0;
  const bool touching = toi.has_value() || sep0.norm() <= tol;
  c.normal = choose_normal(touching, sep0, feature, /*outward=*/false, rel, tol);
  c.gap = c.normal.dot(sep0);
  return c;
}

std::optional<ContactCandidate> test_vertex_plane(const PreparedSurface& a, int vertex, const CollisionPlane& plane,
                                                  int plane_index, double margin) {
  const double length = plane.normal.norm();
  RECOIL_CHECK(length > 0.0 && std::isfinite(length), "plane " << plane_index << " has no normal");
  const Eigen::Vector3d n = plane.normal / length;
  const Eigen::Vector3d p0 = row(a.surface->x0, vertex), p1 = row(a.surface->x1, vertex);
  const double d0 = n.dot(p0 - plane.point), d1 = n.dot(p1 - plane.point);
  if (!(std::min(d0, d1) <= margin)) return std::nullopt;
  ContactCandidate c;
  c.kind = ContactKind::vertex_plane;
  c.surface_a = a.index;
  c.surface_b = plane_index;
  c.body_a = a.surface->body;
  c.body_b = plane.body;
  c.primitive_a = vertex;
  c.primitive_b = plane_index;
  c.a.count = 1;
  c.a.vertex = {vertex, -1, -1};
  c.a.weight = {1.0, 0.0, 0.0};
  c.plane_point = p0 - d0 * n;
  c.normal = n;
  c.gap = d0;
  if (d0 >= 0.0 && d1 <= 0.0 && d0 > d1) c.toi = d0 / (d0 - d1);
  else if (d0 == 0.0) c.toi = 0.0;
  return c;
}

void finalize_candidates(std::vector<ContactCandidate>& candidates) {
  // Feature key of a vertex-triangle candidate: the vertices of B with a
  // non-zero weight (one, two or three of them), sorted.
  auto feature_key = [](const ContactCandidate& c) {
    std::array<int, 3> feature = {-1, -1, -1};
    int n = 0;
    for (int i = 0; i < c.b.count; ++i)
      if (c.b.weight[i] != 0.0) feature[n++] = c.b.vertex[i];
    // Three-element sort by hand (unused slots stay -1 at the end).
    for (int i = 1; i < n; ++i)
      for (int j = i; j > 0 && feature[j] < feature[j - 1]; --j) std::swap(feature[j], feature[j - 1]);
    return std::array<int, 6>{c.surface_a, c.primitive_a, c.surface_b, feature[0], feature[1], feature[2]};
  };
  auto preferred = [](const ContactCandidate& l, const ContactCandidate& r) {
    const double tl = l.toi.value_or(2.0), tr = r.toi.value_or(2.0);
    if (tl != tr) return tl < tr;
    return l.primitive_b < r.primitive_b;
  };
  std::vector<ContactCandidate> others, vertex_triangle;
  for (ContactCandidate& c : candidates)
    (c.kind == ContactKind::vertex_triangle ? vertex_triangle : others).push_back(std::move(c));
  std::sort(vertex_triangle.begin(), vertex_triangle.end(), [&](const ContactCandidate& l, const ContactCandidate& r) {
    const auto kl = feature_key(l), kr = feature_key(r);
    if (kl != kr) return kl < kr;
    return preferred(l, r);
  });
  std::vector<ContactCandidate> per_feature;
  for (size_t i = 0; i < vertex_triangle.size(); ++i)
    if (i == 0 || feature_key(vertex_triangle[i]) != feature_key(vertex_triangle[i - 1]))
      per_feature.push_back(std::move(vertex_triangle[i]));

  // A vertex against a vertex is found from both sides; the two rows are the
  // same constraint, so only the preferred one (earliest impact, then the
  // smaller (surface, vertex) of side A) is kept.
  auto vertex_pair = [&](const ContactCandidate& c) -> std::optional<std::array<int, 4>> {
    const auto key = feature_key(c);
    if (key[4] != -1) return std::nullopt;  // an edge or the interior of B's triangle
    std::array<int, 2> mine = {c.surface_a, c.primitive_a}, theirs = {c.surface_b, key[3]};
    if (theirs < mine) std::swap(mine, theirs);
    return std::array<int, 4>{mine[0], mine[1], theirs[0], theirs[1]};
  };
  std::map<std::array<int, 4>, size_t> kept;  // vertex pair -> index into per_feature
  std::vector<char> keep(per_feature.size(), 1);
  for (size_t i = 0; i < per_feature.size(); ++i) {
    const auto pair = vertex_pair(per_feature[i]);
    if (!pair) continue;
    const auto [it, inserted] = kept.try_emplace(*pair, i);
    if (inserted) continue;
    const ContactCandidate& other = per_feature[it->second];
    const double t_new = per_feature[i].toi.value_or(2.0), t_old = other.toi.value_or(2.0);
    if (t_new < t_old) {  // the later-listed one impacts first: it wins
      keep[it->second] = 0;
      it->second = i;
    } else {
      keep[i] = 0;
    }
  }
  candidates = std::move(others);
  for (size_t i = 0; i < per_feature.size(); ++i)
    if (keep[i]) candidates.push_back(std::move(per_feature[i]));
  std::sort(candidates.begin(), candidates.end(), candidate_less);
}

}  // namespace recoil::sim
