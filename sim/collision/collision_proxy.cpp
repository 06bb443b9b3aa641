#include "sim/collision/collision_proxy.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/check.h"
#include "sim/collision/embree_scene.h"
#include "sim/collision/exact_distance.h"
#include "sim/geometry/mesh_simplify.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/winding_number.h"

namespace recoil::sim {

namespace {

// Offset passes: the first moves by the deviation, later ones by what the
// bending left outside (a few per mille of it), until that is below
// kSettledShare of the offset so far.
constexpr int kOffsetPasses = 4;
constexpr double kSettledShare = 1e-4;

Eigen::Vector3d vertex_of(const TriMesh& m, int v) { return m.vertices.row(v).transpose(); }

// p minus its nearest point on the surface (#F triangles in `scene`), m.
Eigen::Vector3d from_nearest(const TriMesh& surface, const TriangleScene& scene, const Eigen::Vector3d& p, double radius,
                             std::vector<int>& near) {
  for (int grow = 0; grow < 64; ++grow, radius *= 2.0) {
    near.clear();
    scene.triangles_near(p, radius, near);
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    for (int f : near) {
      const Eigen::Vector3d q = closest_point_on_triangle(p, vertex_of(surface, surface.triangles(f, 0)),
                                                          vertex_of(surface, surface.triangles(f, 1)),
                                                          vertex_of(surface, surface.triangles(f, 2)))
                                    .point;
      if ((p - q).norm() < best) {
        best = (p - q).norm();
        offset = p - q;
      }
    }
    if (best <= radius) return offset;
  }
  return Eigen::Vector3d::Zero();  // unreachable for a non-empty surface: the radius outgrows it
}

// Area-weighted vertex normals, unit (#V by 3).
Points vertex_normals(const TriMesh& m) {
  Points n = Points::Zero(m.num_vertices(), 3);
  for (int f = 0; f < m.num_triangles(); ++f) {
    const Eigen::Vector3d a = vertex_of(m, m.triangles(f, 0)), b = vertex_of(m, m.triangles(f, 1)),
                          c = vertex_of(m, m.triangles(f, 2));
    const Eigen::Vector3d area_normal = (b - a).cross(c - a);  // twice the area, outward
    for (int k = 0; k < 3; ++k) n.row(m.triangles(f, k)) += area_normal.transpose();
  }
  for (int v = 0; v < m.num_vertices(); ++v) {
    const double length = n.row(v).norm();
    if (length > 0.0) n.row(v) /= length;
  }
  return n;
}

}  // namespace

int triangles_for_edge_length(const TriMesh& mesh, double edge) {
  RECOIL_CHECK(edge > 0.0);
  const double count = surface_area(mesh) / (std::sqrt(3.0) / 4.0 * edge * edge);
  return static_cast<int>(std::clamp(std::ceil(count), 4.0, 2e9));
}

double default_collision_edge(double cell, double margin) { return std::max(0.25 * cell, 2.0 * margin); }

int collision_budget(const CollisionSurfaceDesc& desc, const TriMesh& mesh, double cell, double margin) {
  if (desc.keep_mesh) return 0;
  if (desc.max_triangles > 0) return desc.max_triangles;
  return triangles_for_edge_length(mesh, desc.edge_length > 0.0 ? desc.edge_length : default_collision_edge(cell, margin));
}

CollisionProxy make_collision_proxy(EmbreeDevice& device, const TriMesh& mesh, int max_triangles) {
  CollisionProxy out;
  if (max_triangles <= 0 || mesh.num_triangles() <= max_triangles) {
    out.surface = mesh;
    return out;
  }
  const SimplifiedMesh simple = simplify_mesh(mesh, max_triangles);
  if (simple.mesh.num_triangles() >= mesh.num_triangles() || simple.mesh.empty()) {
    out.surface = mesh;
    return out;
  }
  out.simplified = true;
  out.surface = simple.mesh;

  // The deviation: the farthest any original vertex stands out of the
  // simplified surface along its own normal (edge collapses may fold a few
  // small triangles over, so their winding cannot say which side is out).
  // The simplified surface then moves along the same normals (its vertices
  // are original ones), which shifts faces a little less where the surface
  // bends: what is left outside is measured and moved again.
  const double extent = bounding_box(mesh).extent().maxCoeff();
  const double radius = std::max(2.0 * simple.relative_error * extent, 1e-6 * extent);
  const Points mesh_normals = vertex_normals(mesh);
  Points normals(out.surface.num_vertices(), 3);
  for (int v = 0; v < out.surface.num_vertices(); ++v) normals.row(v) = mesh_normals.row(simple.source[v]);
  TriangleScene scene(device, out.surface.vertices, out.surface.triangles, /*dynamic=*/true);
  std::vector<int> near;
  for (int pass = 0; pass < kOffsetPasses; ++pass) {
    // Only a vertex outside the simplified volume counts (an inner part of a
    // many-shelled CAD model sits inside it whatever its normal says); the
    // winding number decides, for the vertices that would raise the offset.
    const WindingNumberTree winding(out.surface);
    double outside = 0.0;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      const double along = mesh_normals.row(v).dot(from_nearest(out.surface, scene, vertex_of(mesh, v), radius, near));
      if (along > outside && std::abs(winding(vertex_of(mesh, v))) < 0.5) outside = along;
    }
    if (!(outside > kSettledShare * out.deviation)) break;
    out.deviation += outside;
    out.surface.vertices += outside * normals;
    scene.update_vertices(out.surface.vertices);
  }
  return out;
}

}  // namespace recoil::sim
