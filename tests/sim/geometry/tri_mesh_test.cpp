#include "sim/geometry/tri_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace recoil::sim {

TEST(TriMesh, AppendReindexesAndTransformKeepsOrientation) {
  TriMesh a;
  a.vertices.resize(3, 3);
  a.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  a.triangles.resize(1, 3);
  a.triangles << 0, 1, 2;
  TriMesh b = a;
  append(a, b);
  ASSERT_EQ(a.num_vertices(), 6);
  EXPECT_EQ(a.triangles(1, 0), 3);
  EXPECT_EQ(a.triangles(1, 2), 5);

  transform_in_place(b, Eigen::Matrix3d::Identity(), Eigen::Vector3d(-2, 1, 1), Eigen::Vector3d(0, 0, 1));
  EXPECT_DOUBLE_EQ(b.vertices(1, 0), -2.0);
  EXPECT_DOUBLE_EQ(b.vertices(1, 2), 1.0);
  // Mirrored: the winding flips so the normal keeps pointing out (+z).
  const Eigen::Vector3d e1 = (b.vertices.row(b.triangles(0, 1)) - b.vertices.row(b.triangles(0, 0))).transpose();
  const Eigen::Vector3d e2 = (b.vertices.row(b.triangles(0, 2)) - b.vertices.row(b.triangles(0, 0))).transpose();
  EXPECT_GT(e1.cross(e2).z(), 0.0);

  const Aabb box = bounding_box(a);
  EXPECT_TRUE(box.valid());
  EXPECT_DOUBLE_EQ(box.max.x(), 1.0);
}

}  // namespace recoil::sim
