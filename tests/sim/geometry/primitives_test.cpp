#include "sim/geometry/primitives.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/geometry/mesh_stats.h"

namespace recoil::sim {

constexpr double kPi = 3.14159265358979323846;

// Every primitive must be closed, manifold, outward-oriented, and enclose the
// analytic volume (within the polygonal approximation error).
void expect_closed_with_volume(const TriMesh& mesh, double expected_volume, double relative_tolerance,
                               const char* name) {
  const MeshStats stats = compute_mesh_stats(mesh);
  EXPECT_TRUE(stats.watertight) << name << ": boundary " << stats.boundary_edges << ", non-manifold "
                                << stats.non_manifold_edges << ", inconsistent " << stats.inconsistent_edges;
  EXPECT_EQ(stats.components, 1) << name;
  EXPECT_NEAR(stats.volume / expected_volume, 1.0, relative_tolerance) << name;
  std::cout << name << ": " << stats.triangles << " triangles, volume ratio " << stats.volume / expected_volume
            << "\n";
}

TEST(Primitives, ClosedOutwardAndRightVolume) {
  expect_closed_with_volume(make_box({0.2, 0.4, 0.6}), 0.2 * 0.4 * 0.6, 1e-12, "box");
  expect_closed_with_volume(make_box({1, 1, 1}, 1), 1.0, 1e-12, "box, 1 cell");
  expect_closed_with_volume(make_sphere(0.5), 4.0 / 3.0 * kPi * 0.125, 0.02, "sphere");
  expect_closed_with_volume(make_cylinder(0.1, 1.0), kPi * 0.01 * 1.0, 0.01, "cylinder");
  expect_closed_with_volume(make_capsule(0.1, 0.3), kPi * 0.01 * 0.3 + 4.0 / 3.0 * kPi * 0.001, 0.02, "capsule");
  expect_closed_with_volume(make_capsule(0.1, 0.0), 4.0 / 3.0 * kPi * 0.001, 0.02, "capsule, no shaft");
  expect_closed_with_volume(make_torus(0.3, 0.1), 2 * kPi * kPi * 0.3 * 0.01, 0.02, "torus");
}

TEST(Primitives, CentredOnOrigin) {
  const Aabb box = bounding_box(make_box({0.2, 0.4, 0.6}));
  EXPECT_NEAR(box.min.y(), -0.2, 1e-12);
  EXPECT_NEAR(box.max.z(), 0.3, 1e-12);
  const Aabb cyl = bounding_box(make_cylinder(0.1, 1.0));
  EXPECT_NEAR(cyl.max.y(), 0.5, 1e-12);
  const Aabb torus = bounding_box(make_torus(0.3, 0.1));
  EXPECT_NEAR(torus.max.y(), 0.1, 1e-3);
  EXPECT_NEAR(torus.max.x(), 0.4, 1e-12);
}

TEST(MeshStats, DetectsOpenAndFlippedSurfaces) {
  TriMesh open = make_box({1, 1, 1}, 2);
  open.triangles.conservativeResize(open.num_triangles() - 1, 3);
  const MeshStats stats = compute_mesh_stats(open);
  EXPECT_FALSE(stats.watertight);
  EXPECT_EQ(stats.boundary_edges, 3);

  TriMesh flipped = make_box({1, 1, 1}, 2);
  std::swap(flipped.triangles(0, 1), flipped.triangles(0, 2));
  EXPECT_FALSE(compute_mesh_stats(flipped).watertight);
  EXPECT_EQ(compute_mesh_stats(flipped).inconsistent_edges, 3);

  TriMesh two = make_sphere(1, 1);
  TriMesh other = make_sphere(1, 1);
  other.vertices.col(0).array() += 5;
  append(two, other);
  EXPECT_EQ(compute_mesh_stats(two).components, 2);
  EXPECT_TRUE(compute_mesh_stats(two).watertight);
}

}  // namespace recoil::sim
