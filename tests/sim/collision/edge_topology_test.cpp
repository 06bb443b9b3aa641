// The edge topology the narrow phase reads (narrow_phase.h): each edge's two
// third vertices in winding order, and whether a surface counts as closed.
// The crossed-edge rule trusts both, so a mesh wound the wrong way round in
// places, or open, must not pass as closed.
#include <gtest/gtest.h>

#include "sim/collision/narrow_phase.h"
#include "tests/sim/collision/collision_test_meshes.h"

namespace recoil::sim {
namespace {

// Whether triangle t of `triangles` runs from vertex a straight to vertex b.
bool runs(const Triangles& triangles, Eigen::Index t, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (triangles(t, k) == a && triangles(t, (k + 1) % 3) == b) return true;
  return false;
}

// The triangle holding vertices a, b and c, or -1.
Eigen::Index triangle_of(const Triangles& triangles, int a, int b, int c) {
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    int found = 0;
    for (int k = 0; k < 3; ++k) found += triangles(t, k) == a || triangles(t, k) == b || triangles(t, k) == c;
    if (found == 3) return t;
  }
  return -1;
}

TEST(EdgeTopology, ClosedBoxHasBothThirdVerticesInWindingOrder) {
  const TriMesh box = testing::box({0.1, 0.2, 0.3});
  const auto edges = unique_edges(box.triangles);
  const auto opposite = edge_opposites(box.triangles, edges);
  ASSERT_EQ(edges.size(), 18u);  // 12 box edges and 6 face diagonals
  for (size_t e = 0; e < edges.size(); ++e) {
    const int lo = edges[e][0], hi = edges[e][1];
    ASSERT_GE(opposite[e][0], 0);
    ASSERT_GE(opposite[e][1], 0);
    // Slot 0 is the triangle that runs lo -> hi, slot 1 the one running back.
    EXPECT_TRUE(runs(box.triangles, triangle_of(box.triangles, lo, hi, opposite[e][0]), lo, hi)) << lo << "-" << hi;
    EXPECT_TRUE(runs(box.triangles, triangle_of(box.triangles, lo, hi, opposite[e][1]), hi, lo)) << lo << "-" << hi;
  }
  const CollisionSurface surface = testing::moving_surface(box, 1, BodyKind::deformable, Eigen::Vector3d::Zero());
  EXPECT_TRUE(prepare_surface(surface, 0).closed);
}

TEST(EdgeTopology, OpenOrMiswoundSurfacesAreNotClosed) {
  // A sheet: its border edges have one triangle.
  const TriMesh sheet = testing::grid(3, 0.01);
  EXPECT_FALSE(prepare_surface(testing::moving_surface(sheet, 1, BodyKind::fixed, Eigen::Vector3d::Zero()), 0).closed);
  // A box with one triangle turned round: its three edges each have two
  // triangles running the same way.
  TriMesh box = testing::box({0.1, 0.1, 0.1});
  std::swap(box.triangles(0, 1), box.triangles(0, 2));
  const auto edges = unique_edges(box.triangles);
  const auto opposite = edge_opposites(box.triangles, edges);
  int unwound = 0;
  for (size_t e = 0; e < edges.size(); ++e) {
    const bool on_turned = runs(box.triangles, 0, edges[e][0], edges[e][1]) || runs(box.triangles, 0, edges[e][1], edges[e][0]);
    EXPECT_EQ(opposite[e][0] < 0, on_turned) << edges[e][0] << "-" << edges[e][1];
    unwound += opposite[e][0] < 0;
  }
  EXPECT_EQ(unwound, 3);
  EXPECT_FALSE(prepare_surface(testing::moving_surface(box, 1, BodyKind::deformable, Eigen::Vector3d::Zero()), 0).closed);
}

}  // namespace
}  // namespace recoil::sim
