#include "sim/collision/cone_verdict.h"

#include "sim/collision/ccd.h"
#include "sim/collision/exact_distance.h"
#include "sim/collision/feature_cone.h"

namespace recoil::sim {
namespace {

// The triangles of `s` that hold every vertex of `feature` (1 to 3, as
// SurfacePoint::touched_feature gives them): a vertex's ring, an edge's two
// triangles, or the triangle itself, ascending; and their unit outward
// normals at positions `at`. Degenerate and covered triangles are left
// out. `cone` is cleared first.
struct FeatureCone {
  std::vector<int> faces;
  std::vector<Eigen::Vector3d> normals;
};
template <typename At>
void feature_cone(const PreparedSurface& s, const std::array<int, 3>& feature, At at, FeatureCone& cone) {
  cone.faces.clear();
  cone.normals.clear();
  const Triangles& tri = s.surface->triangles;
  const int v = feature[0];
  const VertexFaces& around = *s.vertex_faces;
  for (int i = around.start[static_cast<size_t>(v)]; i < around.start[static_cast<size_t>(v) + 1]; ++i) {
    const int f = around.faces[static_cast<size_t>(i)];
    bool holds = true;
    for (int w : feature) holds = holds && (w < 0 || tri(f, 0) == w || tri(f, 1) == w || tri(f, 2) == w);
    if (!holds) continue;
    if (is_covered(s, f)) continue;
    const Eigen::Vector3d n = face_normal(at(tri(f, 0)), at(tri(f, 1)), at(tri(f, 2)));
    if (n.isZero()) continue;
    cone.faces.push_back(f);
    cone.normals.push_back(n.normalized());
  }
}

}  // namespace

ConeVerdict judge_by_feature_cones(const PreparedSurface& a, int vertex, const PreparedSurface& b, int triangle,
                                   const SurfacePoint& exact, const Eigen::Vector3d& sep0, const Eigen::Vector3d& rel,
                                   double margin, double tol, ContactCandidate& c) {
  const CollisionSurface& sa = *a.surface;
  const CollisionSurface& sb = *b.surface;
  const double s = c.toi.value_or(0.0);
  auto at_a = [&](int v) { return lerp(point_at(sa.x0, v), point_at(sa.x1, v), s); };
  auto at_b = [&](int v) { return lerp(point_at(sb.x0, v), point_at(sb.x1, v), s); };
  // Reused across calls (this runs for every nearby pair of two closed
  // surfaces): each search thread allocates its cones once, not per pair.
  struct Scratch {
    FeatureCone cone_a, cone_b;
    std::vector<Eigen::Vector3d> generators_a, generators_b;
  };
  thread_local Scratch scratch;
  const std::array<int, 3> feature = exact.touched_feature();
  if (feature[0] < 0) return ConeVerdict::undecided;
  feature_cone(b, feature, at_b, scratch.cone_b);
  feature_cone(a, {vertex, -1, -1}, at_a, scratch.cone_a);
  const FeatureCone& cone_b = scratch.cone_b;
  const FeatureCone& cone_a = scratch.cone_a;
  if (cone_b.normals.empty() || cone_a.normals.empty()) return ConeVerdict::undecided;
  const Eigen::Vector3d aim = rel.norm() > 0.0 ? Eigen::Vector3d(-rel.normalized()) : Eigen::Vector3d::Zero();
  // At an impact p is within rounding of the feature, and d the side it
  // meets it from.
  const Eigen::Vector3d d =
      c.toi ? Eigen::Vector3d(at_a(vertex) - lerp(exact.evaluate(sb.x0), exact.evaluate(sb.x1), s)) : sep0;
  distinct_directions(cone_b.normals, scratch.generators_b);
  distinct_directions(cone_a.normals, scratch.generators_a);
  const std::vector<Eigen::Vector3d>& generators_b = scratch.generators_b;
  const std::vector<Eigen::Vector3d>& generators_a = scratch.generators_a;
  std::optional<ConeNormal> chosen = feature_cone_normal(d, aim, generators_b, generators_a);
  if (c.toi && !chosen)
    chosen = impact_cone_normal(aim, generators_b, sep0, margin);
  if (!chosen) return ConeVerdict::no_contact;
  // An impact on a face that p started behind is its way out of B after
  // crossing another face first, which that crossing holds.
  if (c.toi && chosen->normal.dot(sep0) < -tol) return ConeVerdict::no_contact;
  // The normal of other faces of the feature, one of which p lies over: that
  // face's own pair gives the same row.
  if (chosen->source >= 0 && chosen->source < static_cast<int>(generators_b.size())) {
    for (size_t i = 0; i < cone_b.faces.size(); ++i) {
      const int face = cone_b.faces[i];
      if (face == triangle || (cone_b.normals[i] - chosen->normal).squaredNorm() >= 1e-24) continue;
      const TriangleClosestPoint over = closest_point_on_triangle(
          at_a(vertex), at_b(sb.triangles(face, 0)), at_b(sb.triangles(face, 1)), at_b(sb.triangles(face, 2)));
      if (over.weight[0] > 0.0 && over.weight[1] > 0.0 && over.weight[2] > 0.0) return ConeVerdict::no_contact;
    }
  }
  c.normal = chosen->normal;
  c.gap = c.normal.dot(point_at(sa.x0, vertex) - c.b.evaluate(sb.x0));
  return ConeVerdict::contact;
}

}  // namespace recoil::sim
