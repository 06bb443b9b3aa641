#include "render/vertex_normals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/render/test_meshes.h"

namespace recoil::render {
namespace {

TEST(VertexNormals, SphereNormalsPointRadially) {
  const RenderMesh sphere = test::make_icosphere({0.2f, -0.1f, 0.3f}, 0.7f, 3, {1, 1, 1});
  std::vector<float> normals;
  area_weighted_normals(sphere.positions, sphere.indices, normals);
  ASSERT_EQ(normals.size(), sphere.positions.size());
  double worst = 1.0;
  for (size_t v = 0; v < normals.size(); v += 3) {
    const double rx = sphere.positions[v] - 0.2, ry = sphere.positions[v + 1] + 0.1, rz = sphere.positions[v + 2] - 0.3;
    const double r = std::sqrt(rx * rx + ry * ry + rz * rz);
    const double n = std::sqrt(normals[v] * normals[v] + normals[v + 1] * normals[v + 1] + normals[v + 2] * normals[v + 2]);
    EXPECT_NEAR(n, 1.0, 1e-5);
    worst = std::min(worst, (rx * normals[v] + ry * normals[v + 1] + rz * normals[v + 2]) / r);
  }
  std::cout << "worst cosine to the radial direction: " << worst << "\n";
  EXPECT_GT(worst, 0.999);
}

TEST(VertexNormals, WeightsFacesByArea) {
  // Vertex 0 is shared by a big triangle in the z=0 plane (normal +z) and a
  // small one in the x=0 plane (normal +x): the normal leans towards +z by
  // the area ratio.
  const std::vector<float> positions = {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 1, 0, 0, 0, 1};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 3, 4};
  std::vector<float> normals;
  area_weighted_normals(positions, indices, normals);
  // Areas 8 and 0.5: direction (0.5, 0, 8) normalised.
  const double length = std::sqrt(0.25 + 64.0);
  EXPECT_NEAR(normals[0], 0.5 / length, 1e-6);
  EXPECT_NEAR(normals[1], 0.0, 1e-6);
  EXPECT_NEAR(normals[2], 8.0 / length, 1e-6);
}

TEST(VertexNormals, UnusedAndDegenerateVerticesGetAFiniteNormal) {
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 2, 0, 0, 5, 5, 5};  // a degenerate triangle + a loose vertex
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  std::vector<float> normals;
  area_weighted_normals(positions, indices, normals);
  for (float n : normals) EXPECT_TRUE(std::isfinite(n));
  EXPECT_EQ(normals[10], 1.0f);
}

}  // namespace
}  // namespace recoil::render
