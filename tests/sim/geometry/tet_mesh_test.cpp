// TetMesh basics: orientation repair, unused-node removal, mirrored
// transforms, and the outward boundary of a small mesh.
#include "sim/geometry/tet_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "sim/geometry/boundary.h"
#include "sim/geometry/mesh_stats.h"

namespace recoil::sim {
namespace {

// Two tets sharing face (1, 2, 3), one of them wound negatively, plus an unused node.
TetMesh two_tets() {
  TetMesh m;
  m.nodes.resize(6, 3);
  m.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 9, 9, 9;
  m.tets.resize(2, 4);
  m.tets << 0, 1, 2, 3, 4, 1, 2, 3;
  return m;
}

TEST(TetMesh, OrientationUnusedNodesAndMirroring) {
  TetMesh m = two_tets();
  EXPECT_LT(tet_volume(m, 1), 0.0);
  int degenerate = -1;
  EXPECT_EQ(orient_positive(m, &degenerate), 1);
  EXPECT_EQ(degenerate, 0);
  EXPECT_GT(tet_volume(m, 1), 0.0);
  EXPECT_NEAR(total_volume(m), 1.0 / 6.0 + 1.0 / 3.0, 1e-15);

  const Eigen::VectorXi map = remove_unused_nodes(m);
  EXPECT_EQ(m.num_nodes(), 5);
  EXPECT_EQ(map[5], -1);
  EXPECT_EQ(map[4], 4);

  transform_in_place(m, Eigen::Matrix3d::Identity(), Eigen::Vector3d(-2, 1, 1), Eigen::Vector3d(0, 1, 0));
  for (int t = 0; t < m.num_tets(); ++t) EXPECT_GT(tet_volume(m, t), 0.0);
  EXPECT_NEAR(total_volume(m), 2.0 * (1.0 / 6.0 + 1.0 / 3.0), 1e-14);
}

TEST(TetMesh, BoundaryIsClosedOutwardAndSkipsSharedFaces) {
  TetMesh m = two_tets();
  orient_positive(m);
  remove_unused_nodes(m);
  const TriMesh b = boundary_surface(m);
  EXPECT_EQ(b.num_triangles(), 6);  // 8 faces minus the shared pair
  EXPECT_EQ(b.num_vertices(), m.num_nodes());
  const MeshStats s = compute_mesh_stats(b);
  EXPECT_TRUE(s.watertight);
  EXPECT_NEAR(enclosed_volume(b), total_volume(m), 1e-15);  // positive: outward
}

}  // namespace
}  // namespace recoil::sim
