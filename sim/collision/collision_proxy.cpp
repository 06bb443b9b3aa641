#include "sim/collision/collision_proxy.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/check.h"
#include "sim/collision/embree_scene.h"
#include "sim/collision/exact_distance.h"
#include "sim/geometry/mesh_refine.h"
#include "sim/geometry/mesh_simplify.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/winding_number.h"

namespace recoil::sim {

namespace {

// Offset passes: the first moves each vertex by its deviation, later ones by
// what the bending left outside, until that is below kSettledShare of the
// largest offset so far.
constexpr int kOffsetPasses = 4;
constexpr double kSettledShare = 1e-4;

// p minus its nearest point on the surface (#F triangles in `scene`), m, and
// the triangle that point lies on.
struct Nearest {
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  int triangle = -1;
};
Nearest from_nearest(const TriMesh& surface, const TriangleScene& scene, const Eigen::Vector3d& p, double radius,
                     std::vector<int>& near) {
  for (int grow = 0; grow < 64; ++grow, radius *= 2.0) {
    near.clear();
    scene.triangles_near(p, radius, near);
    double best = std::numeric_limits<double>::infinity();
    Nearest out;
    for (int f : near) {
      const Eigen::Vector3d q = closest_point_on_triangle(p, point_at(surface.vertices, surface.triangles(f, 0)),
                                                          point_at(surface.vertices, surface.triangles(f, 1)),
                                                          point_at(surface.vertices, surface.triangles(f, 2)))
                                    .point;
      if ((p - q).norm() < best) {
        best = (p - q).norm();
        out = {p - q, f};
      }
    }
    if (best <= radius) return out;
  }
  return {};  // unreachable for a non-empty surface: the radius outgrows it
}

// Area-weighted vertex normals, unit (#V by 3).
Points vertex_normals(const TriMesh& m) {
  Points n = Points::Zero(m.num_vertices(), 3);
  for (int f = 0; f < m.num_triangles(); ++f) {
    const Eigen::Vector3d a = point_at(m.vertices, m.triangles(f, 0)), b = point_at(m.vertices, m.triangles(f, 1)),
                          c = point_at(m.vertices, m.triangles(f, 2));
    const Eigen::Vector3d area_normal = (b - a).cross(c - a);  // twice the area, outward
    for (int k = 0; k < 3; ++k) n.row(m.triangles(f, k)) += area_normal.transpose();
  }
  for (int v = 0; v < m.num_vertices(); ++v) {
    const double length = n.row(v).norm();
    if (length > 0.0) n.row(v) /= length;
  }
  return n;
}

// The simplified surface `simple` of `mesh`, each vertex moved out along its
// original normal so that the original vertices end up inside it (within
// kOffsetPasses passes; a thin part may keep a little outside). An original
// vertex standing out of its nearest simplified triangle by a distance a
// along its own normal (edge collapses may fold a few small triangles over,
// so their winding cannot say which side is out) moves that triangle's
// vertices out by a; where the surface bends the face moves a little less,
// so what is left outside is measured and moved again. Each part of the
// surface thus moves by its own deviation: a thin part lost in the
// simplification (a finger) does not push the whole body off the ground.
CollisionProxy offset_outward(EmbreeDevice& device, const TriMesh& mesh, const Points& mesh_normals,
                              const SimplifiedMesh& simple) {
  CollisionProxy out;
  out.separate = true;
  out.surface = simple.mesh;
  const int n = out.surface.num_vertices();
  const double extent = bounding_box(mesh).extent().maxCoeff();
  const double radius = std::max(2.0 * simple.relative_error * extent, 1e-6 * extent);
  Points normals(n, 3);
  for (int v = 0; v < n; ++v) normals.row(v) = mesh_normals.row(simple.source[v]);
  Eigen::VectorXd moved = Eigen::VectorXd::Zero(n);  // m, along `normals`
  TriangleScene scene(device, out.surface.vertices, out.surface.triangles, /*dynamic=*/true);
  std::vector<int> near;
  for (int pass = 0; pass < kOffsetPasses; ++pass) {
    // Only a vertex outside the simplified volume counts (an inner part of a
    // many-shelled CAD model sits inside it whatever its normal says); the
    // winding number decides, for the vertices that would move something.
    const WindingNumberTree winding(out.surface);
    Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      const Nearest q = from_nearest(out.surface, scene, point_at(mesh.vertices, v), radius, near);
      if (q.triangle < 0) continue;
      const double along = mesh_normals.row(v).dot(q.offset);
      double least = along;
      for (int k = 0; k < 3; ++k) least = std::min(least, step[out.surface.triangles(q.triangle, k)]);
      if (!(along > least) || std::abs(winding(point_at(mesh.vertices, v))) >= 0.5) continue;
      for (int k = 0; k < 3; ++k) {
        double& s = step[out.surface.triangles(q.triangle, k)];
        s = std::max(s, along);
      }
    }
    if (!(step.maxCoeff() > kSettledShare * moved.maxCoeff())) break;
    moved += step;
    out.surface.vertices += step.asDiagonal() * normals;
    scene.update_vertices(out.surface.vertices);
  }
  out.deviation = n > 0 ? moved.maxCoeff() : 0.0;
  return out;
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

CollisionProxy make_collision_proxy(EmbreeDevice& device, const TriMesh& mesh, int max_triangles, double max_edge) {
  CollisionProxy out;
  out.surface = mesh;
  if (max_triangles > 0 && mesh.num_triangles() > max_triangles) {
    const SimplifiedMesh simple = simplify_mesh(mesh, max_triangles);
    if (simple.mesh.num_triangles() < mesh.num_triangles() && !simple.mesh.empty())
      out = offset_outward(device, mesh, vertex_normals(mesh), simple);
  }
  // Splitting straight edges keeps the shape exactly: no further offset. An
  // edge as long as the bound but for rounding (a lattice-matched face's
  // diagonal) is not split.
  const double bound = max_edge * (1.0 + 1e-9);
  if (max_edge > 0.0 && longest_edge(out.surface) > bound) {
    out.surface = split_long_edges(out.surface, bound);
    out.separate = true;
  }
  out.surface.look.reset();  // contact's surface is never drawn
  return out;
}

}  // namespace recoil::sim
