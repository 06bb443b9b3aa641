#include "sim/collision/embree_scene.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace recoil::sim {

// A unit square in the z = 0 plane made of two triangles.
static TriMesh unit_square() {
  TriMesh m;
  m.vertices.resize(4, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 0, 2, 3;
  return m;
}

TEST(EmbreeScene, RayHitsSquareAndRefitMovesIt) {
  EmbreeDevice device;
  TriMesh square = unit_square();
  TriangleScene scene(device, square.vertices, square.triangles, /*dynamic=*/true);
  const auto hit = scene.first_hit({0.25, 0.6, 1.0}, {0, 0, -1});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 1.0, 1e-6);
  EXPECT_EQ(hit->triangle, 1);
  EXPECT_FALSE(scene.first_hit({2.0, 0.5, 1.0}, {0, 0, -1}).has_value());
  EXPECT_FALSE(scene.first_hit({0.25, 0.6, 1.0}, {0, 0, -1}, 0.0, 0.5).has_value());

  square.vertices.col(2).array() -= 2.0;  // move to z = -2
  scene.update_vertices(square.vertices);
  const auto moved = scene.first_hit({0.25, 0.6, 1.0}, {0, 0, -1});
  ASSERT_TRUE(moved.has_value());
  EXPECT_NEAR(moved->t, 3.0, 1e-6);
}

TEST(EmbreeScene, AllHitsCountsLayers) {
  EmbreeDevice device;
  TriMesh two = unit_square();
  TriMesh upper = unit_square();
  upper.vertices.col(2).array() += 1.0;
  append(two, upper);
  TriangleScene scene(device, two.vertices, two.triangles, false);
  EXPECT_EQ(scene.all_hits({0.3, 0.7, 5.0}, {0, 0, -1}).size(), 2u);
}

TEST(EmbreeScene, TrianglesNearIsASupersetOfTheExactAnswer) {
  EmbreeDevice device;
  TriMesh square = unit_square();
  TriangleScene scene(device, square.vertices, square.triangles, true);
  std::vector<int> near;
  scene.triangles_near({0.9, 0.1, 0.05}, 0.06, near);  // only triangle 0 is within 6 cm
  ASSERT_FALSE(near.empty());
  EXPECT_EQ(near.front(), 0);
  EXPECT_TRUE(std::is_sorted(near.begin(), near.end()));
  near.clear();
  scene.triangles_near({0.5, 0.5, 0.2}, 0.2, near);  // touching exactly at the diagonal
  EXPECT_EQ(near, (std::vector<int>{0, 1}));
}

TEST(EmbreeScene, BoxPairsOverlapIncludingTouching) {
  EmbreeDevice device;
  BoxScene a(device), b(device);
  auto box = [](double x0, double x1) {
    Aabb box;
    box.min = Eigen::Vector3d(x0, 0, 0);
    box.max = Eigen::Vector3d(x1, 1, 1);
    return box;
  };
  a.set_boxes({box(0, 1), box(2, 3), box(5, 6)});
  b.set_boxes({box(1, 2), box(3.5, 4), box(5.5, 5.6)});
  using Pairs = std::vector<std::pair<int, int>>;
  EXPECT_EQ(a.overlapping_pairs(b), (Pairs{{0, 0}, {1, 0}, {2, 2}}));
  // Refit with the same count, then a rebuild with a new count.
  b.set_boxes({box(10, 11), box(0.5, 0.6), box(20, 21)});
  EXPECT_EQ(a.overlapping_pairs(b), (Pairs{{0, 1}}));
  b.set_boxes({box(2.5, 2.6)});
  EXPECT_EQ(a.overlapping_pairs(b), (Pairs{{1, 0}}));
  EXPECT_TRUE(a.overlapping_pairs(a).empty());  // self: distinct boxes only
  a.set_boxes({box(0, 1), box(0.5, 3), box(5, 6), box(2.5, 5)});
  EXPECT_EQ(a.overlapping_pairs(a), (Pairs{{0, 1}, {1, 3}, {2, 3}}));
  // Keys (say, edge end vertices): boxes sharing one are not paired with each other.
  a.set_boxes({box(0, 1), box(0.5, 3), box(5, 6), box(2.5, 5)}, {{{0, 1}}, {{1, 2}}, {{3, 4}}, {{5, 6}}});
  EXPECT_EQ(a.overlapping_pairs(a), (Pairs{{1, 3}, {2, 3}}));
}

}  // namespace recoil::sim
