#include "sim/collision/initial_overlap.h"

#include <array>
#include <limits>
#include <memory>
#include <set>

#include "sim/collision/exact_distance.h"
#include "sim/geometry/winding_number.h"

namespace recoil::sim {
namespace {


bool boxes_overlap(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

double distance_to_surface(const Eigen::Vector3d& p, const Points& x, const Triangles& triangles) {
  double best = std::numeric_limits<double>::infinity();
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const TriangleClosestPoint c = closest_point_on_triangle(p, x.row(triangles(f, 0)).transpose(),
                                                             x.row(triangles(f, 1)).transpose(),
                                                             x.row(triangles(f, 2)).transpose());
    best = std::min(best, (p - c.point).norm());
  }
  return best;
}

}  // namespace

std::optional<SurfaceOverlap> deepest_overlap(const std::vector<CollisionSurface>& surfaces,
                                              const std::vector<CollisionPlane>& planes,
                                              const std::vector<ContactCandidate>& near, double margin) {
  // (surface, vertex, other surface) triples within the margin.
  std::set<std::array<int, 3>> within_margin;
  for (const ContactCandidate& c : near)
    if (c.kind == ContactKind::vertex_triangle) within_margin.insert({c.surface_a, c.primitive_a, c.surface_b});
  std::optional<SurfaceOverlap> deepest;
  auto consider = [&](const SurfaceOverlap& o) {
    if (o.depth > margin && (!deepest || o.depth > deepest->depth)) deepest = o;
  };
  for (size_t s = 0; s < surfaces.size(); ++s) {
    if (is_prescribed(surfaces[s].kind)) continue;
    for (size_t p = 0; p < planes.size(); ++p) {
      const Eigen::Vector3d n = planes[p].normal.normalized();
      const double lowest = ((surfaces[s].x0.rowwise() - planes[p].point.transpose()) * n).minCoeff();
      consider({static_cast<int>(s), -1, static_cast<int>(p), -lowest});
    }
  }
  std::vector<Aabb> boxes;
  for (const CollisionSurface& s : surfaces) boxes.push_back(bounding_box(s.x0));
  std::vector<std::unique_ptr<WindingNumberTree>> trees(surfaces.size());  // built when first needed
  int probes = 0;  // exact depths measured: each costs a pass over the other surface's triangles
  for (size_t a = 0; a < surfaces.size(); ++a) {
    for (size_t b = 0; b < surfaces.size(); ++b) {
      if (a == b || (is_prescribed(surfaces[a].kind) && is_prescribed(surfaces[b].kind))) continue;
      if (!boxes_overlap(boxes[a], boxes[b])) continue;
      const CollisionSurface& inner = surfaces[a];
      const CollisionSurface& outer = surfaces[b];
      if (!trees[b]) trees[b] = std::make_unique<WindingNumberTree>(TriMesh{outer.x0, outer.triangles, nullptr});
      for (Eigen::Index v = 0; v < inner.x0.rows() && probes < kDepthProbes; ++v) {
        const Eigen::Vector3d p = inner.x0.row(v).transpose();
        if ((p.array() < boxes[b].min.array()).any() || (p.array() > boxes[b].max.array()).any()) continue;
        if (!((*trees[b])(p) > 0.5)) continue;
        if (within_margin.count({static_cast<int>(a), static_cast<int>(v), static_cast<int>(b)})) continue;
        ++probes;
        consider({static_cast<int>(a), static_cast<int>(b), -1, distance_to_surface(p, outer.x0, outer.triangles)});
      }
    }
  }
  return deepest;
}

}  // namespace recoil::sim
