#include "render/crease_split.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>

#include "render/renderer.h"
#include "tests/render/test_meshes.h"

namespace recoil::render {
namespace {

// The same surface with coincident vertices merged (first occurrence wins).
RenderMesh weld(const RenderMesh& mesh) {
  RenderMesh welded;
  welded.color = mesh.color;
  welded.opacity = mesh.opacity;
  std::map<std::array<float, 3>, std::uint32_t> seen;
  std::vector<std::uint32_t> remap;
  for (size_t v = 0; v < mesh.positions.size(); v += 3) {
    const std::array<float, 3> p = {mesh.positions[v], mesh.positions[v + 1], mesh.positions[v + 2]};
    auto [it, inserted] = seen.emplace(p, static_cast<std::uint32_t>(welded.positions.size() / 3));
    if (inserted) welded.positions.insert(welded.positions.end(), p.begin(), p.end());
    remap.push_back(it->second);
  }
  for (std::uint32_t i : mesh.indices) welded.indices.push_back(remap[i]);
  return welded;
}

TEST(CreaseSplit, BoxCornersSplitIntoOneVertexPerFace) {
  const RenderMesh box = weld(test::make_box({0, 0, 0}, {1, 1, 1}, {1, 1, 1}));
  ASSERT_EQ(box.positions.size(), 8u * 3);
  const CreaseSplit split = split_creases(box.positions, box.indices, 40.0);
  EXPECT_FALSE(split.identity);
  EXPECT_EQ(split.source.size(), 24u);  // each corner on 3 faces
  ASSERT_EQ(split.indices.size(), box.indices.size());
  for (size_t c = 0; c < box.indices.size(); ++c) EXPECT_EQ(split.source[split.indices[c]], box.indices[c]);
}

TEST(CreaseSplit, SmoothSurfacesAreLeftAlone) {
  const RenderMesh sphere = test::make_icosphere({0, 0, 0}, 1.0f, 2, {1, 1, 1});
  const CreaseSplit split = split_creases(sphere.positions, sphere.indices, 40.0);
  EXPECT_TRUE(split.identity);
  EXPECT_EQ(split.indices, sphere.indices);
  // At a 5 degree threshold the same sphere's facets separate.
  EXPECT_FALSE(split_creases(sphere.positions, sphere.indices, 5.0).identity);
}

TEST(CreaseSplit, RecognisesClosedOrientedMeshes) {
  auto closed = [](const std::vector<std::uint32_t>& indices, const std::vector<float>& positions) {
    return split_creases(positions, indices, 40.0).closed;
  };
  const RenderMesh sphere = test::make_icosphere({0, 0, 0}, 1.0f, 1, {1, 1, 1});
  const RenderMesh torus = test::make_torus({0, 0, 0}, 1.0f, 0.3f, 12, 8, {1, 1, 1});
  const RenderMesh box = test::make_box({0, 0, 0}, {1, 1, 1}, {1, 1, 1});
  EXPECT_TRUE(closed(sphere.indices, sphere.positions));
  EXPECT_TRUE(closed(torus.indices, torus.positions));
  EXPECT_TRUE(closed(weld(box).indices, weld(box).positions));
  // Split faces leave every edge a border.
  EXPECT_FALSE(closed(box.indices, box.positions));
  std::vector<std::uint32_t> flipped = sphere.indices;
  std::swap(flipped[0], flipped[1]);
  EXPECT_FALSE(closed(flipped, sphere.positions));
  std::vector<std::uint32_t> holed(sphere.indices.begin(), sphere.indices.end() - 3);
  EXPECT_FALSE(closed(holed, sphere.positions));
  // Two copies on the same vertices: every edge used four times.
  std::vector<std::uint32_t> doubled = sphere.indices;
  doubled.insert(doubled.end(), sphere.indices.begin(), sphere.indices.end());
  EXPECT_FALSE(closed(doubled, sphere.positions));
  EXPECT_FALSE(closed({}, sphere.positions));
}

TEST(CreaseSplit, SharedVertexBoxRendersLikeSplitBox) {
  // Smooth normals would round a welded box off; the split keeps it flat
  // shaded, so it renders exactly like the box built with split faces.
  RenderSettings settings;
  settings.width = 96;
  settings.height = 64;
  settings.msaa = 0;
  // The welded box is closed, so its shadow pass culls faces turned from the
  // light, which moves shadow edges by a texel; compare unshadowed frames.
  settings.shadows = false;
  const RenderMesh split_box = test::make_box({0, 0.5f, 0}, {1, 1, 1}, {0.8f, 0.6f, 0.4f});
  const Camera camera = frame_bounding_sphere({0, 0.5, 0}, 0.9, 30, 25, 40, 1.5);
  Renderer renderer(settings);
  RenderScene scene;
  scene.meshes = {split_box};
  const Image reference = renderer.render(scene, camera);
  scene.meshes = {weld(split_box)};
  const Image welded = renderer.render(scene, camera);
  // The welded box is also closed, so its back faces are culled; the split
  // one draws them and may show one on a silhouette pixel where the two tie
  // in depth. Everything else must match exactly.
  int differing = 0;
  for (size_t i = 0; i < reference.rgba.size(); i += 4) {
    differing += !std::equal(reference.rgba.begin() + static_cast<std::ptrdiff_t>(i),
                             reference.rgba.begin() + static_cast<std::ptrdiff_t>(i + 4),
                             welded.rgba.begin() + static_cast<std::ptrdiff_t>(i));
  }
  std::cout << "pixels differing between welded and split box: " << differing << " of " << reference.rgba.size() / 4
            << "\n";
  EXPECT_LE(differing, 3);
}

}  // namespace
}  // namespace recoil::render
