// Splitting long edges: every edge ends at most the asked length, the shape
// and its enclosed volume are exactly the input's, the surface stays closed
// and conforming, and the same input gives the same output.
#include "sim/geometry/mesh_refine.h"

#include <gtest/gtest.h>

#include "sim/geometry/mesh_stats.h"
#include "sim/geometry/primitives.h"

namespace recoil::sim {
namespace {

TEST(MeshRefine, ABoxOfTwelveTrianglesGetsEdgesNoLongerThanAsked) {
  const TriMesh box = make_box(Eigen::Vector3d(1.0, 0.5, 0.25), 1);
  ASSERT_EQ(box.num_triangles(), 12);
  const TriMesh fine = split_long_edges(box, 0.1);
  EXPECT_LE(longest_edge(fine), 0.1);
  EXPECT_GT(fine.num_triangles(), 12 * 20);
  const MeshStats before = compute_mesh_stats(box), after = compute_mesh_stats(fine);
  EXPECT_TRUE(after.watertight);  // closed, consistently wound: no T-junction opened a crack
  EXPECT_NEAR(after.volume, before.volume, 1e-12);
  EXPECT_NEAR(after.area, before.area, 1e-12);
  // Every new vertex lies on the box's surface.
  for (int v = 0; v < fine.num_vertices(); ++v) {
    const Eigen::Vector3d p = fine.vertices.row(v).transpose().cwiseAbs();
    const double outside = std::max({p.x() - 0.5, p.y() - 0.25, p.z() - 0.125});
    EXPECT_NEAR(outside, 0.0, 1e-12) << v;
  }
  const TriMesh again = split_long_edges(box, 0.1);
  EXPECT_EQ(again.vertices, fine.vertices);
  EXPECT_EQ(again.triangles, fine.triangles);
}

TEST(MeshRefine, AMeshAlreadyFineIsUnchanged) {
  const TriMesh sphere = make_sphere(0.1, 3);
  const TriMesh same = split_long_edges(sphere, 1.0);
  EXPECT_EQ(same.vertices, sphere.vertices);
  EXPECT_EQ(same.triangles, sphere.triangles);
}

}  // namespace
}  // namespace recoil::sim
