#include "render/mesh_topology.h"

#include <gtest/gtest.h>

#include "tests/render/test_meshes.h"

namespace recoil::render {
namespace {

TEST(MeshTopology, ClosedOrientedMeshesAreRecognised) {
  EXPECT_TRUE(is_closed_oriented(test::make_icosphere({0, 0, 0}, 1.0f, 2, {1, 1, 1}).indices));
  EXPECT_TRUE(is_closed_oriented(test::make_torus({0, 0, 0}, 1.0f, 0.3f, 12, 8, {1, 1, 1}).indices));
}

TEST(MeshTopology, OpenFlippedOrNonManifoldMeshesAreNot) {
  // The test box has split faces (24 vertices): its edges are open borders.
  EXPECT_FALSE(is_closed_oriented(test::make_box({0, 0, 0}, {1, 1, 1}, {1, 1, 1}).indices));
  RenderMesh sphere = test::make_icosphere({0, 0, 0}, 1.0f, 1, {1, 1, 1});
  std::swap(sphere.indices[0], sphere.indices[1]);  // one face flipped
  EXPECT_FALSE(is_closed_oriented(sphere.indices));
  sphere = test::make_icosphere({0, 0, 0}, 1.0f, 1, {1, 1, 1});
  sphere.indices.resize(sphere.indices.size() - 3);  // a hole
  EXPECT_FALSE(is_closed_oriented(sphere.indices));
  // Two copies of a closed mesh glued on the same vertices: every edge used four times.
  sphere = test::make_icosphere({0, 0, 0}, 1.0f, 1, {1, 1, 1});
  std::vector<std::uint32_t> doubled = sphere.indices;
  doubled.insert(doubled.end(), sphere.indices.begin(), sphere.indices.end());
  EXPECT_FALSE(is_closed_oriented(doubled));
  EXPECT_FALSE(is_closed_oriented({}));
}

}  // namespace
}  // namespace recoil::render
