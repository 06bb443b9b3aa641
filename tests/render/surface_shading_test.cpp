// glTF's metallic-roughness factors on the studio shading: a material
// without them keeps the studio's highlight, roughness sets the highlight's
// width and peak, and a metal's highlight takes its base colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "render/renderer.h"
#include "render/surface_shading.h"
#include "tests/render/test_meshes.h"

namespace recoil::render {
namespace {

TEST(SurfaceShading, WithoutFactorsTheStudioHighlightIsKept) {
  const SurfaceShading plain = surface_shading(RenderMaterial{});
  EXPECT_EQ(plain.metallic, 0.0f);
  EXPECT_EQ(plain.shininess, 48.0f);
  EXPECT_EQ(plain.highlight, 1.0f);
}

TEST(SurfaceShading, RoughnessSetsTheLobeThroughTheBeckmannSlope) {
  RenderMaterial m;
  m.has_surface = true;
  m.roughness = 0.2f;  // alpha 0.04: e = 2 / 0.0016 - 2
  EXPECT_NEAR(surface_shading(m).shininess, 1248.0f, 0.5f);
  EXPECT_NEAR(surface_shading(m).highlight, 1256.0f / 56.0f, 0.01f);
  m.roughness = std::sqrt(std::sqrt(0.04f));  // the studio's own lobe
  EXPECT_NEAR(surface_shading(m).shininess, 48.0f, 0.01f);
  m.roughness = 1.0f;  // matte: the widest lobe, at 9/56 of the studio's peak
  EXPECT_EQ(surface_shading(m).shininess, 1.0f);
  EXPECT_NEAR(surface_shading(m).highlight, 9.0f / 56.0f, 1e-6f);
  m.roughness = 0.0f;  // a mirror's lobe is clamped, never infinite
  EXPECT_EQ(surface_shading(m).shininess, 4096.0f);
}

// A red sphere lit by the studio rig, 96 x 96, drawn with one material.
Image red_sphere(const RenderMaterial& material) {
  RenderMesh sphere = test::make_icosphere({0.0f, 0.0f, 0.0f}, 1.0f, 4, {1.0f, 1.0f, 1.0f});
  auto look = std::make_shared<RenderLook>();
  const size_t faces = sphere.indices.size() / 3;
  look->corner_colors.resize(9 * faces);
  for (size_t c = 0; c < 3 * faces; ++c) {
    look->corner_colors[3 * c] = 0.6f;
    look->corner_colors[3 * c + 1] = 0.05f;
    look->corner_colors[3 * c + 2] = 0.05f;
  }
  look->triangle_materials.assign(faces, 0u);
  look->materials = {material};
  sphere.look = look;
  RenderSettings settings;
  settings.width = 96;
  settings.height = 96;
  settings.msaa = 0;
  settings.shadows = false;
  RenderScene scene;
  scene.ground = false;
  scene.meshes = {sphere};
  Camera camera;
  camera.eye = {0.0, 1.5, 4.0};
  camera.target = {0.0, 0.0, 0.0};
  camera.fov_y_degrees = 40.0;
  return Renderer(settings).render(scene, camera);
}

// The brightest pixel's (r, g, b), by green (the highlight's own channel on red).
std::array<int, 3> brightest(const Image& image) {
  std::array<int, 3> best{0, 0, 0};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[1] > best[1]) best = {p[0], p[1], p[2]};
    }
  return best;
}

TEST(SurfaceShading, GlossyMattAndMetalSpheresDiffer) {
  RenderMaterial matte, glossy, metal;
  matte.has_surface = glossy.has_surface = metal.has_surface = true;
  matte.roughness = 1.0f;
  glossy.roughness = 0.25f;
  metal.roughness = 0.45f;  // about the studio's lobe, so the peak does not clip
  metal.metallic = 1.0f;
  const auto studio = brightest(red_sphere(RenderMaterial{}));
  const auto m = brightest(red_sphere(matte));
  const auto g = brightest(red_sphere(glossy));
  const auto t = brightest(red_sphere(metal));
  // A white highlight lifts green on a red body; a matte one barely does.
  EXPECT_GT(studio[1], m[1] + 40) << studio[1] << " " << m[1];
  EXPECT_GT(g[1], studio[1]) << g[1] << " " << studio[1];
  // A metal's highlight is its own red: green stays far below red.
  EXPECT_GT(t[0], t[1] + 100) << t[0] << " " << t[1];
  EXPECT_GT(studio[1], t[1] + 60) << studio[1] << " " << t[1];
}

}  // namespace
}  // namespace recoil::render
