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

#include "render/png.h"
#include "render/renderer.h"
#include "tests/render/test_meshes.h"
#include "tests/test_support.h"

namespace recoil::render {
namespace {

struct Difference {
  long failing = 0;       // pixels with some channel off by more than the tolerance
  double fraction = 0.0;  // failing / pixels
  int worst = 0;          // largest channel difference seen (0-255)
};

// A pixel fails when any channel (alpha included) differs by more than
// `tolerance` levels. (render/image_metrics will replace this at integration.)
Difference compare(const Image& a, const Image& b, int tolerance) {
  Difference d;
  if (a.width != b.width || a.height != b.height) {
    d.failing = std::max<long>(1, static_cast<long>(a.width) * a.height);
    d.fraction = 1.0;
    return d;
  }
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    int pixel_worst = 0;
    for (size_t c = 0; c < 4; ++c) pixel_worst = std::max(pixel_worst, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
    d.worst = std::max(d.worst, pixel_worst);
    d.failing += pixel_worst > tolerance;
  }
  d.fraction = static_cast<double>(d.failing) / (static_cast<double>(a.rgba.size()) / 4.0);
  return d;
}

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
  const Difference d = compare(actual, expected, 2);
  std::cout << name << ": " << d.failing << " pixels off by > 2/255 (" << 100.0 * d.fraction
            << " %), worst channel difference " << d.worst << "\n";
  if (d.fraction > 0.001) {
    const auto dir = recoil::test::scratch_dir("golden_" + name);
    write_png(dir / (name + ".png"), actual);
    ADD_FAILURE() << name << ": " << 100.0 * d.fraction << " % of pixels differ (limit 0.1 %); actual image in "
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
