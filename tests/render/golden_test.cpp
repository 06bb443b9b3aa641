// Golden images of small scenes, compared with a tolerance so that another
// llvmpipe build (vector width, LLVM version) may differ in a few pixels.
//
// To regenerate after an intended change of the look, run
//   RECOIL_UPDATE_GOLDEN=1 build/recoil_tests_render --gtest_filter='Golden*'
// then look at tests/render/golden/*.png before committing them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <string>

#include "render/image_metrics.h"
#include "render/png.h"
#include "render/renderer.h"
#include "tests/render/test_meshes.h"
#include "tests/test_support.h"

namespace recoil::render {
namespace {

void check_golden(const std::string& name, const Image& actual) {
  const auto golden = recoil::test::source_path("tests/render/golden/" + name + ".png");
  const char* update = std::getenv("RECOIL_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    write_png(golden, actual);
    std::cout << "updated " << golden << "\n";
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing; run with RECOIL_UPDATE_GOLDEN=1";
  const Image expected = read_png(golden);
  ASSERT_EQ(actual.width, expected.width) << name;
  ASSERT_EQ(actual.height, expected.height) << name;
  // The project's visual-regression metric (recoil compare): a pixel fails
  // when a channel differs by more than 2/255; at most 0.1 % may fail.
  const ImageComparison d = compare_images(actual, expected, 2.0 / 255.0);
  std::cout << name << ": " << d.failing_pixels << " pixels off by > 2/255 (" << 100.0 * d.failing_fraction
            << " %), max difference " << d.max_difference << ", SSIM " << d.ssim << "\n";
  if (d.failing_fraction > 0.001) {
    const auto dir = recoil::test::scratch_dir("golden_" + name);
    write_png(dir / (name + ".png"), actual);
    ADD_FAILURE() << name << ": " << 100.0 * d.failing_fraction << " % of pixels differ (limit 0.1 %); actual image in "
                  << (dir / (name + ".png"));
  }
}

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
