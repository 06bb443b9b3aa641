// Collision surfaces: a fine mesh gets a simplified, outward-offset copy
// that holds the original inside it; a coarse one is its own.
#include "sim/collision/collision_proxy.h"

#include <gtest/gtest.h>

#include <iostream>

#include "sim/collision/embree_scene.h"
#include "sim/geometry/mesh_import.h"
#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/primitives.h"
#include "sim/rigid/mass_properties.h"

namespace recoil::sim {
namespace {

// How far p stands outside a surface star-shaped about the origin: |p| minus
// the distance at which the ray from the origin towards p meets the surface
// (turned by 1e-6 rad, since a ray straight through a shared vertex may slip
// between Embree's float triangles).
double outside_distance(const TriangleScene& surface, const Eigen::Vector3d& p) {
  const auto hit = surface.first_hit(Eigen::Vector3d::Zero(), (p.normalized() + Eigen::Vector3d(1e-6, 0.7e-6, 0.3e-6)).normalized());
  EXPECT_TRUE(hit.has_value());
  return hit ? p.norm() - hit->t : 0.0;
}

TEST(CollisionProxy, AFineMeshGetsASimplifiedSurfaceThatHoldsItInside) {
  EmbreeDevice device;
  const TriMesh fine = make_sphere(0.1, 6);
  const int budget = collision_budget({}, fine, 0.2 / 8, 0.002);
  const CollisionProxy proxy = make_collision_proxy(device, fine, budget);
  std::cout << fine.num_triangles() << " triangles -> " << proxy.surface.num_triangles() << " (budget " << budget
            << "), offset " << proxy.deviation * 1e3 << " mm\n";
  ASSERT_TRUE(proxy.separate);
  EXPECT_LE(proxy.surface.num_triangles(), budget);
  EXPECT_GT(proxy.surface.num_triangles(), budget / 2);
  EXPECT_GT(proxy.deviation, 0.0);
  EXPECT_LT(proxy.deviation, 0.01 * 0.1);  // a smooth sphere at a few thousand triangles deviates well under 1 % of its radius
  const TriangleScene scene(device, proxy.surface.vertices, proxy.surface.triangles, false);
  double worst = -1.0;
  for (int v = 0; v < fine.num_vertices(); ++v)
    worst = std::max(worst, outside_distance(scene, fine.vertices.row(v).transpose()));
  std::cout << "farthest original vertex outside the collision surface: " << worst * 1e3 << " mm\n";
  EXPECT_LE(worst, 1e-3 * proxy.deviation);
  // Closed and outward: its volume is a little larger than the original's.
  EXPECT_GT(enclosed_volume(proxy.surface), enclosed_volume(fine));
}

TEST(CollisionProxy, ThinPartsLostInTheSimplificationMoveOnlyTheirOwnRegionOut) {
  // A scanned-looking human from Debian's assimp-testmodels (28 796
  // triangles, 1.66 m, open), at the budget `drop` gives it (resolution 8:
  // cells of 0.207 m): its fingers and toes are thinner than the collision
  // edge, and the simplification flattens them.
  const TriMesh human = import_surface("/usr/share/assimp/models/Collada/human.zae");
  EmbreeDevice device;
  const CollisionProxy proxy = make_collision_proxy(device, human, collision_budget({}, human, 0.2074, 0.002));
  ASSERT_TRUE(proxy.separate);
  const double bottom = human.vertices.col(1).minCoeff() - proxy.surface.vertices.col(1).minCoeff();
  std::cout << proxy.surface.num_triangles() << " collision triangles, largest offset " << proxy.deviation * 1e3
            << " mm, below the feet " << bottom * 1e3 << " mm\n";
  // The largest offset is the fingers'; the soles move by their own, so the
  // body stands on the ground at a fraction of it.
  EXPECT_GT(proxy.deviation, 0.02);
  EXPECT_GE(bottom, 0.0);
  EXPECT_LT(bottom, 0.5 * proxy.deviation);
}

TEST(CollisionProxy, ACoarseMeshIsItsOwnCollisionSurface) {
  EmbreeDevice device;
  const TriMesh box = make_box({0.2, 0.2, 0.2}, 8);
  const CollisionProxy proxy = make_collision_proxy(device, box, collision_budget({}, box, 0.2 / 8, 0.002));
  EXPECT_FALSE(proxy.separate);
  EXPECT_EQ(proxy.surface.vertices, box.vertices);
  EXPECT_EQ(proxy.deviation, 0.0);
  CollisionSurfaceDesc keep;
  keep.keep_mesh = true;
  EXPECT_EQ(collision_budget(keep, make_sphere(0.1, 6), 0.025, 0.002), 0);
}

TEST(CollisionProxy, BudgetFollowsTheEdgeLength) {
  const TriMesh sphere = make_sphere(1.0, 5);
  // Area 4 pi, equilateral triangles of edge 0.1: 4 pi / (sqrt(3) / 4 * 0.01) = 2902.
  CollisionSurfaceDesc edge;
  edge.edge_length = 0.1;
  EXPECT_NEAR(collision_budget(edge, sphere, 0.25, 0.002), 2902, 30);
  // The default never goes below twice the margin.
  EXPECT_DOUBLE_EQ(default_collision_edge(0.01, 0.002), 0.004);
  EXPECT_DOUBLE_EQ(default_collision_edge(0.2, 0.002), 0.05);
}

}  // namespace
}  // namespace recoil::sim
