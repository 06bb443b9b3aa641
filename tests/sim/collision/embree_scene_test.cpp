#include "sim/collision/embree_scene.h"

#include <gtest/gtest.h>

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

}  // namespace recoil::sim
