// Golden images of small scenes, compared with a tolerance so that another
// llvmpipe build (vector width, LLVM version) may differ in a few pixels.
//
// To regenerate after an intended change of the look, run
//   RECOIL_UPDATE_GOLDEN=1 build/recoil_tests_render --gtest_filter='Golden*'
// then look at tests/render/golden/*.png before committing them.
#include <gtest/gtest.h>

#include "render/renderer.h"
#include "tests/render/golden_check.h"
#include "tests/render/test_meshes.h"
#include "tests/test_support.h"

namespace recoil::render {
namespace {

RenderSettings golden_settings(int width, int height) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.msaa = 4;
  settings.shadows = true;
  return settings;
}

TEST(Golden, LitBoxWithShadowOnGridFloor) {
  const RenderSettings settings = golden_settings(256, 192);
  RenderScene scene;
  scene.meshes.push_back(test::make_box({0.0f, 0.4f, 0.0f}, {0.8f, 0.8f, 0.8f}, {0.85f, 0.63f, 0.40f}));
  scene.meshes.push_back(test::make_box({0.75f, 0.15f, 0.45f}, {0.3f, 0.3f, 0.3f}, {0.55f, 0.75f, 0.45f}));
  const Camera camera = frame_bounding_sphere({0.2, 0.35, 0.1}, 1.0, -25.0, 25.0, 40.0, 256.0 / 192.0);
  check_golden("box_shadow", Renderer(settings).render(scene, camera));
}

TEST(Golden, TransparentSphereOverOpaqueTorus) {
  const RenderSettings settings = golden_settings(256, 192);
  RenderScene scene;
  scene.meshes.push_back(test::make_torus({0.0f, 0.25f, 0.0f}, 0.6f, 0.25f, 48, 24, {0.25f, 0.45f, 0.85f}));
  RenderMesh sphere = test::make_icosphere({0.25f, 0.45f, 0.45f}, 0.45f, 3, {0.90f, 0.30f, 0.25f});
  sphere.opacity = 0.45f;
  scene.meshes.push_back(sphere);
  const Camera camera = frame_bounding_sphere({0.05, 0.35, 0.1}, 1.1, 20.0, 30.0, 40.0, 256.0 / 192.0);
  check_golden("transparent_overlap", Renderer(settings).render(scene, camera));
}

TEST(Golden, IcosphereWithMsaaNoGrid) {
  RenderSettings settings = golden_settings(192, 192);
  RenderScene scene;
  scene.grid = false;
  scene.meshes.push_back(test::make_icosphere({0.0f, 0.5f, 0.0f}, 0.5f, 2, {0.80f, 0.80f, 0.82f}));
  const Camera camera = frame_bounding_sphere({0.0, 0.4, 0.0}, 0.75, 0.0, 15.0, 40.0, 1.0);
  check_golden("icosphere_msaa", Renderer(settings).render(scene, camera));
}

}  // namespace
}  // namespace recoil::render
