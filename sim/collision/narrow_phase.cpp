#include "sim/collision/narrow_phase.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/check.h"
#include "sim/collision/ccd.h"
#include "sim/collision/cone_verdict.h"
#include "sim/collision/exact_distance.h"
#include "sim/collision/rest_clearance.h"

namespace recoil::sim {
namespace {

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

Eigen::Vector3d edge_cross(const Eigen::Vector3d& da, const Eigen::Vector3d& db) {
  const Eigen::Vector3d n = da.cross(db);
  return n.squaredNorm() > 1e-24 * da.squaredNorm() * db.squaredNorm() ? n : Eigen::Vector3d::Zero();
}

// Zeroes the smallest weights of a closest point q on triangle t while the
// snapped point stays within `reach` of q, then renormalises (the largest
// weight always stays). A vertex a few microns off a neighbour's vertex or
// edge names that vertex or edge: the same feature from every triangle
// around it, so the reduction keeps one contact.
std::array<double, 3> snap_to_feature(const std::array<double, 3>& w, const std::array<Eigen::Vector3d, 3>& t,
                                      double reach) {
  auto point = [&](const std::array<double, 3>& v) { return v[0] * t[0] + v[1] * t[1] + v[2] * t[2]; };
  const Eigen::Vector3d q = point(w);
  std::array<int, 3> order = {0, 1, 2};  // by weight, then index: the same on every standard library
  std::sort(order.begin(), order.end(), [&](int l, int r) {
    return std::make_pair(w[static_cast<size_t>(l)], l) < std::make_pair(w[static_cast<size_t>(r)], r);
  });
  std::array<double, 3> snapped = w;
  for (int i = 0; i < 2; ++i) {
    std::array<double, 3> next = snapped;
    next[static_cast<size_t>(order[static_cast<size_t>(i)])] = 0.0;
    const double sum = next[0] + next[1] + next[2];
    for (double& wi : next) wi /= sum;
    if ((point(next) - q).norm() >= reach) break;
    snapped = next;
  }
  return snapped;
}

bool on_triangle_boundary(const std::array<double, 3>& w) { return w[0] == 0.0 || w[1] == 0.0 || w[2] == 0.0; }

// The unit normals at x0 of the two triangles across `edge` (of a
// manifold, consistently wound edge): (lo, hi, o0) and (hi, lo, o1), so both
// point out of a counter-clockwise surface. False when either is lost in
// rounding.
bool edge_face_normals(const PreparedSurface& s, int edge, Eigen::Vector3d& n_forward, Eigen::Vector3d& n_back) {
  const std::array<int, 2> ends = s.edges[static_cast<size_t>(edge)];
  const std::array<int, 2> opposite = s.edge_opposite[static_cast<size_t>(edge)];
  const Points& x = s.surface->x0;
  const Eigen::Vector3d lo = point_at(x, ends[0]), hi = point_at(x, ends[1]);
  n_forward = face_normal(lo, hi, point_at(x, opposite[0]));
  n_back = face_normal(hi, lo, point_at(x, opposite[1]));
  if (n_forward.isZero() || n_back.isZero()) return false;
  n_forward.normalize();
  n_back.normalize();
  return true;
}

// How far (m) the surface departs from a plane across `edge` at x0: the
// larger distance of each of its triangles' third vertex from the other
// triangle's plane; infinite on a boundary, non-manifold or degenerate edge.
double edge_bend(const PreparedSurface& s, int edge) {
  const std::array<int, 2> opposite = s.edge_opposite[static_cast<size_t>(edge)];
  Eigen::Vector3d n_forward, n_back;
  if (opposite[0] < 0 || !edge_face_normals(s, edge, n_forward, n_back)) return std::numeric_limits<double>::infinity();
  const Points& x = s.surface->x0;
  const Eigen::Vector3d lo = point_at(x, s.edges[static_cast<size_t>(edge)][0]);
  return std::max(std::abs(n_forward.dot(point_at(x, opposite[1]) - lo)), std::abs(n_back.dot(point_at(x, opposite[0]) - lo)));
}

// Whether direction d (unit) leaves the surface across `edge` into its
// inside: below both its triangles' planes (counter-clockwise from outside),
// d . n below -kInsideCosine for each. Needs a closed surface's edge.
constexpr double kInsideCosine = 0.1;
bool points_inside_at_edge(const PreparedSurface& s, int edge, const Eigen::Vector3d& d) {
  Eigen::Vector3d n_forward, n_back;
  if (!edge_face_normals(s, edge, n_forward, n_back)) return false;
  return d.dot(n_forward) < -kInsideCosine && d.dot(n_back) < -kInsideCosine;
}

// Whether vertex v lies inside a flat patch at x0: the surface is closed (so
// its triangles close round v; a sheet's border vertex can be the patch's
// lowest point) and its uncovered triangles lie within `tolerance` (m) of
// one plane, as edge_bend measures it (each ring vertex off each ring
// plane). Where covered triangles stand in the ring the fixed bodies
// together continue the patch or rise from it (a seam, a concave corner),
// and the free space there is convex: the patch's border still holds.
bool flat_vertex(const PreparedSurface& s, int v, double tolerance) {
  if (!s.closed) return false;
  const Triangles& tri = s.surface->triangles;
  const Points& x = s.surface->x0;
  const VertexFaces& around = *s.vertex_faces;
  const int first = around.start[static_cast<size_t>(v)], last = around.start[static_cast<size_t>(v) + 1];
  const Eigen::Vector3d origin = point_at(x, v);
  bool any = false;
  for (int i = first; i < last; ++i) {
    const int f = around.faces[static_cast<size_t>(i)];
    if (is_covered(s, f)) continue;
    any = true;
    const Eigen::Vector3d n = face_normal(point_at(x, tri(f, 0)), point_at(x, tri(f, 1)), point_at(x, tri(f, 2)));
    if (n.isZero()) return false;
    const Eigen::Vector3d unit = n.normalized();
    for (int j = first; j < last; ++j) {
      const int g = around.faces[static_cast<size_t>(j)];
      if (is_covered(s, g)) continue;
      for (int k = 0; k < 3; ++k)
        if (std::abs(unit.dot(point_at(x, tri(g, k)) - origin)) > tolerance) return false;
    }
  }
  return any;
}

// Whether vertex v is a flat vertex of a body that keeps its shape, never a
// candidate (narrow_phase.h): deformable patches are flat at x0 only.
// Flat means coplanar to the precision a mesh file's float coordinates
// carry (relative kCoplanarShare of the body's size), not within a share of
// the margin: a finely faceted ball is flat within that at every vertex, and
// with none of them a candidate it fell through the ground.
constexpr double kCoplanarShare = 1e-7;
bool in_rigid_flat_patch(const PreparedSurface& s, int v) {
  if (s.surface->kind == BodyKind::deformable || !s.box0.valid()) return false;
  return flat_vertex(s, v, kCoplanarShare * s.box0.extent().norm());
}

// Whether a covered triangle holds `edge` (its lower vertex's ring is searched).
bool beside_covered_face(const PreparedSurface& s, int edge) {
  if (s.covered == nullptr) return false;
  const std::array<int, 2> ends = s.edges[static_cast<size_t>(edge)];
  const Triangles& tri = s.surface->triangles;
  const VertexFaces& around = *s.vertex_faces;
  for (int i = around.start[static_cast<size_t>(ends[0])]; i < around.start[static_cast<size_t>(ends[0]) + 1]; ++i) {
    const int f = around.faces[static_cast<size_t>(i)];
    if (is_covered(s, f) && (tri(f, 0) == ends[1] || tri(f, 1) == ends[1] || tri(f, 2) == ends[1])) return true;
  }
  return false;
}

// Whether every triangle around vertex v is covered: v is inside what the
// fixed bodies together enclose.
bool buried_vertex(const PreparedSurface& s, int v) {
  if (s.covered == nullptr) return false;
  const VertexFaces& around = *s.vertex_faces;
  const int first = around.start[static_cast<size_t>(v)], last = around.start[static_cast<size_t>(v) + 1];
  for (int i = first; i < last; ++i)
    if (!is_covered(s, around.faces[static_cast<size_t>(i)])) return false;
  return last > first;
}

}  // namespace

bool edge_may_contact(const PreparedSurface& s, int edge, double margin) {
  return !(edge_bend(s, edge) <= kFeatureSnapShare * margin) && !beside_covered_face(s, edge);
}

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

std::vector<std::array<int, 2>> edge_opposites(const Triangles& triangles, const std::vector<std::array<int, 2>>& edges) {
  std::vector<std::array<int, 2>> opposite(edges.size(), {-1, -1});
  std::vector<int> count(edges.size(), 0);  // triangles seen per edge
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = triangles(f, k), v = triangles(f, (k + 1) % 3);
      const std::array<int, 2> key = {std::min(u, v), std::max(u, v)};
      const auto it = std::lower_bound(edges.begin(), edges.end(), key);
      if (it == edges.end() || *it != key) continue;
      const size_t e = static_cast<size_t>(it - edges.begin());
      // Slot 0: the triangle that runs the edge lo -> hi; slot 1: hi -> lo.
      const size_t slot = u < v ? 0 : 1;
      if (opposite[e][slot] < 0) opposite[e][slot] = triangles(f, (k + 2) % 3);
      else opposite[e][slot] = -2;  // a second triangle the same way round
      ++count[e];
    }
  for (size_t e = 0; e < edges.size(); ++e)
    if (count[e] != 2 || opposite[e][0] < 0 || opposite[e][1] < 0) opposite[e] = {-1, -1};
  return opposite;
}

VertexFaces vertex_faces(const Triangles& triangles, int num_vertices) {
  VertexFaces out;
  out.start.assign(static_cast<size_t>(num_vertices) + 1, 0);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++out.start[static_cast<size_t>(triangles(f, k)) + 1];
  for (int v = 0; v < num_vertices; ++v) out.start[static_cast<size_t>(v) + 1] += out.start[static_cast<size_t>(v)];
  out.faces.resize(static_cast<size_t>(out.start.back()));
  std::vector<int> next(out.start.begin(), out.start.end() - 1);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int k = 0; k < 3; ++k) out.faces[static_cast<size_t>(next[static_cast<size_t>(triangles(f, k))]++)] = static_cast<int>(f);
  return out;
}

PreparedSurface prepare_surface(const CollisionSurface& surface, int index,
                                const std::vector<std::array<int, 2>>* edges,
                                const std::vector<std::array<int, 2>>* edge_opposite,
                                std::shared_ptr<const VertexFaces> faces) {
  RECOIL_CHECK((edges == nullptr) == (edge_opposite == nullptr), "give both edges and their opposite vertices, or neither");
  PreparedSurface out;
  out.surface = &surface;
  out.index = index;
  const int nv = static_cast<int>(surface.x0.rows());
  RECOIL_CHECK(surface.x1.rows() == nv, "surface " << index << ": x0 has " << nv << " rows, x1 " << surface.x1.rows());
  RECOIL_CHECK(surface.x0.allFinite() && surface.x1.allFinite(), "surface " << index << " has non-finite positions");
  RECOIL_CHECK(!(surface.self_contact && surface.kind == BodyKind::deformable) ||
                   (surface.rest != nullptr && surface.rest->rows() == nv),
               "surface " << index << ": self-contact needs the rest shape (#V rows)");
  out.vertex_motion.resize(static_cast<size_t>(nv));
  for (int v = 0; v < nv; ++v) {
    out.box0.extend(point_at(surface.x0, v));
    out.vertex_motion[v] = (point_at(surface.x1, v) - point_at(surface.x0, v)).norm();
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
  out.edge_opposite = edge_opposite ? *edge_opposite : edge_opposites(surface.triangles, out.edges);
  out.vertex_faces = faces ? std::move(faces) : std::make_shared<const VertexFaces>(vertex_faces(surface.triangles, nv));
  out.closed = !out.edges.empty() && std::all_of(out.edge_opposite.begin(), out.edge_opposite.end(),
                                                 [](const std::array<int, 2>& o) { return o[0] >= 0; });
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
  return a.surface->kind == BodyKind::deformable && a.surface->self_contact;
}

namespace {

// The self-contact rule (collision_types.h): how near (m) a pair of one
// surface must come to be a candidate, min(margin, rest distance - margin);
// zero or less for a pair within the margin of each other at rest, never a
// contact.
double self_reach(double rest_distance, double margin) { return std::min(margin, rest_distance - margin); }

// Whether a vertex of one primitive of a self pair moves with the element of
// a vertex of the other, or with one sharing a face with it (collision_types.h);
// `a` and `b` are the primitives' vertices.
template <size_t NA, size_t NB>
bool in_face_adjacent_elements(const CollisionSurface& s, const std::array<int, NA>& a,
                               const std::array<int, NB>& b) {
  if (s.vertex_element == nullptr || s.elements == nullptr) return false;
  for (int va : a)
    for (int vb : b) {
      const auto na = s.elements->row((*s.vertex_element)[va]), nb = s.elements->row((*s.vertex_element)[vb]);
      int shared = 0;  // nodes in common: 4 for one element, 3 for a shared face
      for (int i = 0; i < 4; ++i) shared += (nb.array() == na[i]).any() ? 1 : 0;
      if (shared >= 3) return true;
    }
  return false;
}

// Whether a pair d0 apart at the start of the step and d1 at its end may
// come within `reach` in between, when each point of one primitive moves at
// most `relative` with respect to each point of the other (m): the distance
// then changes by at most relative * |s - s'| between step fractions s and
// s', so it stays above max(d0 - relative s, d1 - relative (1 - s)), whose
// least value is (d0 + d1 - relative) / 2 where the two lines cross.
bool comes_within(double d0, double d1, double reach, double relative) {
  return d0 <= reach + relative && d1 <= reach + relative && d0 + d1 <= 2.0 * reach + relative;
}

}  // namespace
bool interacts_with_planes(const PreparedSurface& a) { return !is_prescribed(a.surface->kind); }


std::optional<ContactCandidate> test_vertex_triangle(const PreparedSurface& a, int vertex, const PreparedSurface& b,
                                                     int triangle, double margin) {
  if (is_covered(b, triangle)) return std::nullopt;  // covered_faces.h
  const CollisionSurface& sa = *a.surface;
  const CollisionSurface& sb = *b.surface;
  const std::array<int, 3> tv = {sb.triangles(triangle, 0), sb.triangles(triangle, 1), sb.triangles(triangle, 2)};

  const Eigen::Vector3d p0 = point_at(sa.x0, vertex), p1 = point_at(sa.x1, vertex);
  std::array<Eigen::Vector3d, 3> t0, t1;
  for (int k = 0; k < 3; ++k) {
    t0[k] = point_at(sb.x0, tv[k]);
    t1[k] = point_at(sb.x1, tv[k]);
  }
  const double motion = a.vertex_motion[vertex] + b.triangle_motion[triangle];
  double relative = 0.0;  // narrow_phase.h: how far p moves with respect to any point of the triangle
  for (int k = 0; k < 3; ++k) relative = std::max(relative, ((p1 - p0) - (t1[k] - t0[k])).norm());
  // The distance to the triangle's box is a lower bound of the distance to
  // it, and far cheaper: most pairs a query offers end here.
  const Eigen::Vector3d box_min = t0[0].cwiseMin(t0[1]).cwiseMin(t0[2]), box_max = t0[0].cwiseMax(t0[1]).cwiseMax(t0[2]);
  if (!((box_min - p0).cwiseMax(p0 - box_max).cwiseMax(0.0).norm() <= margin + relative)) return std::nullopt;
  const TriangleClosestPoint closest = closest_point_on_triangle(p0, t0[0], t0[1], t0[2]);
  const double distance = (p0 - closest.point).norm();
  if (!(distance <= margin + relative)) return std::nullopt;
  // Its ring is walked only for pairs this near.
  if (buried_vertex(a, vertex)) return std::nullopt;
  if (a.index == b.index && in_face_adjacent_elements(sa, std::array<int, 1>{vertex}, tv)) return std::nullopt;
  const double reach = a.index == b.index ? self_reach(rest_distance(*sa.rest, vertex, tv), margin) : margin;
  if (!(reach > 0.0) || !(distance <= reach + relative)) return std::nullopt;
  if (relative > 0.0 &&
      !comes_within(distance, (p1 - closest_point_on_triangle(p1, t1[0], t1[1], t1[2]).point).norm(), reach, relative))
    return std::nullopt;
  // A flat vertex of a body that keeps its shape adds nothing (narrow_phase.h).
  if (in_rigid_flat_patch(a, vertex)) return std::nullopt;

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
  const double snap = kFeatureSnapShare * margin + tol;
  SurfacePoint exact = c.b;  // the true closest point: the normal and gap come from it
  if (c.toi) {
    // Weights and normal where the vertex meets the triangle.
    const double s = *c.toi;
    const Eigen::Vector3d ta = lerp(t0[0], t1[0], s), tb = lerp(t0[1], t1[1], s), tc = lerp(t0[2], t1[2], s);
    exact.weight = closest_point_on_triangle(lerp(p0, p1, s), ta, tb, tc).weight;
    c.b.weight = snap_to_feature(exact.weight, {ta, tb, tc}, snap);
    feature = face_normal(ta, tb, tc);
  } else {
    exact.weight = closest.weight;
    c.b.weight = snap_to_feature(exact.weight, t0, snap);
    feature = face_normal(t0[0], t0[1], t0[2]);
  }
  // The snapped weights name the feature and carry the rows (and the gap);
  // the normal uses the exact point, since a snap of up to margin/10
  // sideways would tilt the normal of a contact resting margin/10 apart by
  // up to 45 degrees.
  const Eigen::Vector3d q0 = exact.evaluate(sb.x0), q1 = exact.evaluate(sb.x1);
  const Eigen::Vector3d sep0 = p0 - q0, rel = (p1 - q1) - sep0;
  const bool touching_at_start = sep0.norm() <= tol;
  if (a.index != b.index && a.closed && b.closed) {
    const ConeVerdict verdict = judge_by_feature_cones(a, vertex, b, triangle, exact, sep0, rel, margin, tol, c);
    if (verdict == ConeVerdict::contact) return c;
    if (verdict == ConeVerdict::no_contact) return std::nullopt;
  }
  // Touching at the start on an edge or vertex of this triangle: its face
  // normal is only one of the feature's normals (a corner resting exactly on
  // a corner touches the top face and both side faces). Only a face that the
  // vertex is moving into defines the contact; the others are left to the
  // neighbouring triangles of the same feature (narrow_phase.h).
  if (touching_at_start && on_triangle_boundary(c.b.weight) && !(feature.dot(rel) < 0.0)) return std::nullopt;
  const bool touching = c.toi.has_value() || touching_at_start;
  c.normal = choose_normal(touching, sep0, feature, /*outward=*/true, rel, tol);
  c.gap = c.normal.dot(p0 - c.b.evaluate(sb.x0));  // with the weights the rows use (collision_types.h)
  return c;
}

std::optional<ContactCandidate> test_edge_edge(const PreparedSurface& a, int edge_a, const PreparedSurface& b,
                                               int edge_b, double margin) {
  const std::array<int, 2> ea = a.edges[edge_a], eb = b.edges[edge_b];
  if (a.index == b.index) RECOIL_CHECK(edge_a < edge_b, "self edge pair " << edge_a << ", " << edge_b << " not ordered");
  const CollisionSurface& sa = *a.surface;
  const CollisionSurface& sb = *b.surface;
  const Eigen::Vector3d a0 = point_at(sa.x0, ea[0]), a1 = point_at(sa.x0, ea[1]);
  const Eigen::Vector3d b0 = point_at(sb.x0, eb[0]), b1 = point_at(sb.x0, eb[1]);
  const Eigen::Vector3d a0e = point_at(sa.x1, ea[0]), a1e = point_at(sa.x1, ea[1]);
  const Eigen::Vector3d b0e = point_at(sb.x1, eb[0]), b1e = point_at(sb.x1, eb[1]);
  double relative = 0.0;  // narrow_phase.h: how far any point of one edge moves with respect to any of the other
  for (const Eigen::Vector3d& da_i : {Eigen::Vector3d(a0e - a0), Eigen::Vector3d(a1e - a1)})
    for (const Eigen::Vector3d& db_j : {Eigen::Vector3d(b0e - b0), Eigen::Vector3d(b1e - b1)})
      relative = std::max(relative, (da_i - db_j).norm());
  // The gap between the edges' boxes bounds their distance from below, cheaply.
  const Eigen::Vector3d box_gap =
      (b0.cwiseMin(b1) - a0.cwiseMax(a1)).cwiseMax(a0.cwiseMin(a1) - b0.cwiseMax(b1)).cwiseMax(0.0);
  if (!(box_gap.norm() <= margin + relative)) return std::nullopt;
  SegmentClosestPoints closest = closest_points_on_segments(a0, a1, b0, b1);
  const double distance = ((a0 + closest.s * (a1 - a0)) - (b0 + closest.t * (b1 - b0))).norm();
  if (!(distance <= margin + relative)) return std::nullopt;
  if (a.index == b.index && in_face_adjacent_elements(sa, ea, eb)) return std::nullopt;
  const double reach = a.index == b.index ? self_reach(rest_distance(*sa.rest, ea, eb), margin) : margin;
  if (!(reach > 0.0) || !(distance <= reach + relative)) return std::nullopt;
  // A flat or covered edge adds nothing its neighbours do not (narrow_phase.h).
  if (!edge_may_contact(a, edge_a, margin) || !edge_may_contact(b, edge_b, margin)) return std::nullopt;

  const double tol = pair_tolerance(a, b);
  const double motion = a.edge_motion[edge_a] + b.edge_motion[edge_b];
  if (relative > 0.0) {
    const SegmentClosestPoints end = closest_points_on_segments(a0e, a1e, b0e, b1e);
    if (!comes_within(distance, ((a0e + end.s * (a1e - a0e)) - (b0e + end.t * (b1e - b0e))).norm(), reach, relative))
      return std::nullopt;
  }
  std::optional<double> toi;
  if (motion > 0.0) toi = edge_edge_toi(a0, a0e, a1, a1e, b0, b0e, b1, b1e, tol + 1e-12 * motion);
  Eigen::Vector3d feature, da = a1 - a0, db = b1 - b0;  // at the impact if there is one
  if (toi) {
    const double s = *toi;
    const Eigen::Vector3d pa = lerp(a0, a0e, s), pb = lerp(b0, b0e, s);
    da = lerp(a1, a1e, s) - pa;
    db = lerp(b1, b1e, s) - pb;
    closest = closest_points_on_segments(pa, pa + da, pb, pb + db);
  }
  feature = edge_cross(da, db);
  // A closest point at (or near) an edge's end is a vertex contact, and
  // nearly parallel edges are held by their end vertices (narrow_phase.h).
  const double snap = kFeatureSnapShare * margin + tol;
  auto near_end = [&](double s, double length) { return std::min(s, 1.0 - s) * length < snap; };
  if (near_end(closest.s, da.norm()) || near_end(closest.t, db.norm())) return std::nullopt;
  // Parallel to within the margin over the longer edge's length: the ends
  // stay within the margin of the other edge, and their vertex-triangle
  // candidates hold the pair, whereas the edges' own closest points could
  // be anywhere along the overlap. Edges crossing at a small angle but
  // drifting apart by more than the margin stay edge-edge candidates.
  const double sine = feature.norm() / (da.norm() * db.norm());
  if (!(sine * std::max(da.norm(), db.norm()) >= margin)) return std::nullopt;

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
  // p - q into B at its edge and q - p into A at its: the edges crossed
  // while no candidate held them (a ridge through a flat face grid), and
  // p - q would hold them crossed. Turned round, the gap is negative and the
  // solver pushes the edges back out. Only between two closed surfaces,
  // where inside means something; not in self-contact, where two edges on
  // either side of a ridge pass this test without having crossed.
  // Only within the margin: "below both planes" means inside only near the
  // edge, and a thin part (an ear) a centimetre off would pass it too.
  if (!toi && a.index != b.index && a.closed && b.closed && sep0.norm() <= margin &&
      points_inside_at_edge(b, edge_b, c.normal) && points_inside_at_edge(a, edge_a, -c.normal))
    c.normal = -c.normal;
  c.gap = c.normal.dot(sep0);
  return c;
}

std::optional<ContactCandidate> test_vertex_plane(const PreparedSurface& a, int vertex, const CollisionPlane& plane,
                                                  int plane_index, double margin) {
  const double length = plane.normal.norm();
  RECOIL_CHECK(length > 0.0 && std::isfinite(length), "plane " << plane_index << " has no normal");
  const Eigen::Vector3d n = plane.normal / length;
  const Eigen::Vector3d p0 = point_at(a.surface->x0, vertex), p1 = point_at(a.surface->x1, vertex);
  const double d0 = n.dot(p0 - plane.point), d1 = n.dot(p1 - plane.point);
  if (!(std::min(d0, d1) <= margin)) return std::nullopt;
  if (in_rigid_flat_patch(a, vertex)) return std::nullopt;  // narrow_phase.h
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

}  // namespace recoil::sim
