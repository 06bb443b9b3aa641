// Behaviour of the offscreen renderer on tiny frames: coverage, clear colour,
// determinism, transparency, MSAA, blending order, wireframe, bad settings.
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "core/error.h"
#include "render/image_metrics.h"
#include "tests/render/test_meshes.h"

namespace recoil::render {
namespace {

// One triangle facing the camera (+z), big enough to cover the centre.
RenderMesh facing_triangle(Rgb color, float z = 0.0f) {
  RenderMesh mesh;
  mesh.positions = {-0.6f, -0.5f, z, 0.6f, -0.5f, z, 0.0f, 0.6f, z};
  mesh.indices = {0, 1, 2};
  mesh.color = color;
  return mesh;
}

Camera front_camera() {
  Camera camera;
  camera.eye = {0.0, 0.0, 3.0};
  camera.target = {0.0, 0.0, 0.0};
  camera.fov_y_degrees = 40.0;
  return camera;
}

RenderSettings small(int msaa, bool shadows = false) {
  RenderSettings settings;
  settings.width = 96;
  settings.height = 64;
  settings.msaa = msaa;
  settings.shadows = shadows;
  return settings;
}

Camera studio_camera(const RenderSettings& s) {
  return frame_bounding_sphere({0.0, 0.5, 0.0}, 1.6, 30.0, 20.0, 40.0, double(s.width) / s.height);
}

std::array<int, 4> at(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2], p[3]};
}

TEST(Renderer, TriangleCoversCentreWithItsColourAndClearColourElsewhere) {
  const RenderSettings settings = small(0);
  Renderer renderer(settings);
  RenderScene scene;
  scene.ground = false;
  for (int channel = 0; channel < 3; ++channel) {
    Rgb color = {0.1f, 0.1f, 0.1f};
    color[static_cast<size_t>(channel)] = 0.9f;
    scene.meshes = {facing_triangle(color)};
    const Image image = renderer.render(scene, front_camera());
    ASSERT_EQ(image.width, 96);
    ASSERT_EQ(image.height, 64);
    const auto centre = at(image, 48, 32);
    std::cout << "channel " << channel << " centre rgba " << centre[0] << " " << centre[1] << " " << centre[2]
              << " " << centre[3] << "\n";
    // Lit by the rig, the triangle keeps its hue: the chosen channel dominates.
    for (int other = 0; other < 3; ++other) {
      if (other != channel) {
        EXPECT_GT(centre[static_cast<size_t>(channel)], 2 * centre[static_cast<size_t>(other)] + 20);
      }
    }
    EXPECT_EQ(centre[3], 255);
    // Corners hold the clear colour #1d2127 exactly.
    for (auto [x, y] : {std::pair{0, 0}, std::pair{95, 0}, std::pair{0, 63}, std::pair{95, 63}}) {
      EXPECT_EQ(at(image, x, y), (std::array<int, 4>{0x1d, 0x21, 0x27, 255})) << x << "," << y;
    }
  }
}

TEST(Renderer, ImageIsTopRowFirst) {
  // A triangle in the upper half of the view lands in the image's first rows.
  Renderer renderer(small(0));
  RenderScene scene;
  scene.ground = false;
  RenderMesh mesh;
  mesh.positions = {-0.5f, 0.2f, 0.0f, 0.5f, 0.2f, 0.0f, 0.0f, 0.9f, 0.0f};
  mesh.indices = {0, 1, 2};
  mesh.color = {0.9f, 0.9f, 0.9f};
  scene.meshes = {mesh};
  const Image image = renderer.render(scene, front_camera());
  EXPECT_GT(at(image, 48, 16)[0], 100);  // upper half: triangle
  EXPECT_EQ(at(image, 48, 48)[0], 0x1d);  // lower half: background
}

TEST(Renderer, SameInputGivesIdenticalBytes) {
  const RenderSettings settings = small(4, true);
  const RenderScene scene = test::studio_scene();
  Renderer renderer(settings);
  const Image first = renderer.render(scene, studio_camera(settings));
  const Image second = renderer.render(scene, studio_camera(settings));
  Renderer fresh(settings);
  const Image third = fresh.render(scene, studio_camera(settings));
  EXPECT_EQ(first.rgba, second.rgba);
  EXPECT_EQ(first.rgba, third.rgba);
}

TEST(Renderer, TransparentBackgroundHasZeroAlphaWhereNothingIsDrawn) {
  RenderSettings settings = small(4, true);
  settings.transparent_background = true;
  Renderer renderer(settings);
  const Image image = renderer.render(test::studio_scene(), studio_camera(settings));
  EXPECT_EQ(at(image, 0, 0)[3], 0);    // sky above the faded floor
  EXPECT_EQ(at(image, 95, 0)[3], 0);
  EXPECT_EQ(at(image, 48, 32)[3], 255);  // the box
  // The floor's rim fades: some pixels are partly transparent.
  int fading = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) fading += (at(image, x, y)[3] > 0 && at(image, x, y)[3] < 255);
  std::cout << "partly transparent pixels: " << fading << "\n";
  EXPECT_GT(fading, 20);
}

TEST(Renderer, TransparentBackgroundStoresStraightAlpha) {
  // A half-transparent body over nothing keeps its lit colour; only alpha drops.
  RenderSettings settings = small(0);
  settings.transparent_background = true;
  Renderer renderer(settings);
  RenderScene scene;
  scene.ground = false;
  RenderMesh mesh = facing_triangle({0.9f, 0.5f, 0.1f});
  scene.meshes = {mesh};
  const auto opaque = at(renderer.render(scene, front_camera()), 48, 32);
  mesh.opacity = 0.5f;
  scene.meshes = {mesh};
  const auto half = at(renderer.render(scene, front_camera()), 48, 32);
  std::cout << "opaque " << opaque[0] << " " << opaque[1] << " " << opaque[2] << " " << opaque[3] << ", half "
            << half[0] << " " << half[1] << " " << half[2] << " " << half[3] << "\n";
  EXPECT_EQ(opaque[3], 255);
  EXPECT_NEAR(half[3], 128, 1);
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(half[c], opaque[c], 3) << "channel " << c;
}

// Edge pixels strictly between the background and a facing triangle, and
// the triangle's centre green, drawn with `msaa` samples.
struct EdgeCount {
  int inside = 0, mixed = 0;
};
EdgeCount edge_pixels(int msaa) {
  RenderScene scene;
  scene.ground = false;
  scene.meshes = {facing_triangle({0.9f, 0.9f, 0.9f})};
  Renderer renderer(small(msaa));
  const Image image = renderer.render(scene, front_camera());
  EdgeCount count;
  count.inside = at(image, 48, 32)[1];
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const int g = at(image, x, y)[1];
      count.mixed += (g > 0x21 + 8 && g < count.inside - 8);
    }
  std::cout << "msaa " << msaa << ": centre green " << count.inside << ", edge pixels " << count.mixed << "\n";
  return count;
}

TEST(Renderer, MsaaSmoothsEdges) {
  const EdgeCount off = edge_pixels(0), four = edge_pixels(4);
  EXPECT_GT(off.inside, 150);
  EXPECT_GT(four.inside, 150);
  EXPECT_LT(off.mixed, 5);
  EXPECT_GT(four.mixed, 30);
}

// Two samples where the driver has them; where it rounds them up
// (llvmpipe: 4 only) the request is refused, naming what it would get.
TEST(Renderer, MsaaTwoIsTwoSamplesOrRefused) {
  try {
    const EdgeCount two = edge_pixels(2);
    EXPECT_GT(two.mixed, 30);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    const std::string message = e.what();
    EXPECT_NE(message.find("render msaa 2: this OpenGL driver"), std::string::npos) << message;
    EXPECT_NE(message.find("use msaa 0 or 4"), std::string::npos) << message;
  }
}

TEST(Renderer, TransparentRedInFrontOfOpaqueBlueLooksPurpleInAnyListOrder) {
  RenderMesh blue = facing_triangle({0.1f, 0.2f, 0.9f}, -0.3f);
  RenderMesh red = facing_triangle({0.9f, 0.1f, 0.1f}, 0.3f);
  red.opacity = 0.5f;
  RenderScene scene;
  scene.ground = false;
  Renderer renderer(small(0));
  scene.meshes = {blue, red};
  const auto first = at(renderer.render(scene, front_camera()), 48, 32);
  scene.meshes = {red, blue};
  const auto second = at(renderer.render(scene, front_camera()), 48, 32);
  std::cout << "blended centre " << first[0] << " " << first[1] << " " << first[2] << "\n";
  EXPECT_EQ(first, second);
  EXPECT_GT(first[0], first[1] + 40);  // red shows
  EXPECT_GT(first[2], first[1] + 40);  // blue shows through
  EXPECT_EQ(first[3], 255);
  // Opaque red would hide the blue.
  red.opacity = 1.0f;
  scene.meshes = {blue, red};
  const auto opaque = at(renderer.render(scene, front_camera()), 48, 32);
  EXPECT_LT(opaque[2], first[2] - 40);
}

TEST(Renderer, WireframeDrawsDarkEdgesOverTheShading) {
  RenderSettings settings = small(0);
  RenderScene scene;
  scene.ground = false;
  scene.meshes = {test::make_icosphere({0, 0, 0}, 0.9f, 1, {0.9f, 0.9f, 0.9f})};
  const Image shaded = Renderer(settings).render(scene, front_camera());
  settings.wireframe = true;
  const Image wire = Renderer(settings).render(scene, front_camera());
  int darker = 0;
  for (size_t i = 0; i < shaded.rgba.size(); i += 4) darker += wire.rgba[i + 1] + 40 < shaded.rgba[i + 1];
  std::cout << "pixels darkened by edges: " << darker << "\n";
  EXPECT_GT(darker, 50);
}

TEST(Renderer, MeshesMayChangeBetweenFrames) {
  // Slots are reused: a frame with fewer meshes or a changed topology must
  // not draw stale data.
  Renderer renderer(small(0));
  RenderScene scene;
  scene.ground = false;
  scene.meshes = {facing_triangle({0.9f, 0.1f, 0.1f}), test::make_box({0, 0, 0}, {0.2f, 0.2f, 0.2f}, {0.1f, 0.9f, 0.1f})};
  renderer.render(scene, front_camera());
  scene.meshes = {test::make_box({0, 0, 0}, {2.0f, 2.0f, 0.2f}, {0.1f, 0.9f, 0.1f})};
  const Image after = renderer.render(scene, front_camera());
  const auto centre = at(after, 48, 32);
  EXPECT_GT(centre[1], 2 * centre[0]);
  const Image fresh = Renderer(small(0)).render(scene, front_camera());
  EXPECT_EQ(after.rgba, fresh.rgba);
}

TEST(Renderer, EmptySceneIsBackgroundAndFloor) {
  const RenderSettings settings = small(4, true);
  Renderer renderer(settings);
  RenderScene scene;
  const Image image = renderer.render(scene, studio_camera(settings));
  EXPECT_EQ(at(image, 0, 0), (std::array<int, 4>{0x1d, 0x21, 0x27, 255}));
}

TEST(Renderer, RejectsBadSettings) {
  RenderSettings settings = small(3);
  EXPECT_THROW(Renderer{settings}, Error);
  settings = small(0);
  settings.width = 0;
  try {
    Renderer renderer(settings);
    FAIL() << "no throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::bad_input);
    EXPECT_NE(std::string(e.what()).find("resolution"), std::string::npos);
  }
}

TEST(Renderer, KeyLightCastsAShadowOnTheFloor) {
  RenderScene scene;
  scene.grid = false;
  scene.meshes = {test::make_box({0.0f, 0.5f, 0.0f}, {1.0f, 1.0f, 1.0f}, {0.8f, 0.8f, 0.8f})};
  Camera camera;
  camera.eye = {0.0, 6.0, 0.01};  // looking down: the whole shadow is in view
  camera.target = {0.0, 0.0, 0.0};
  const Image lit = Renderer(small(4, false)).render(scene, camera);
  const Image shadowed = Renderer(small(4, true)).render(scene, camera);
  int darker = 0, brighter = 0;
  for (size_t i = 0; i < lit.rgba.size(); i += 4) {
    darker += shadowed.rgba[i + 1] + 20 < lit.rgba[i + 1];
    brighter += shadowed.rgba[i + 1] > lit.rgba[i + 1] + 2;
  }
  std::cout << "floor pixels darkened by the shadow: " << darker << " of " << lit.rgba.size() / 4 << "\n";
  EXPECT_GT(darker, 150);  // the box's shadow covers a few hundred pixels here
  EXPECT_EQ(brighter, 0);  // a shadow never adds light
}

// A surface wound inward (an open scan whose faces point in) is lit and
// shadowed as the same surface wound outward: its shadow lookups start on
// the side the key lights, not inside it, where it shadowed itself in stripes.
TEST(Renderer, AnInwardWoundSurfaceIsShadedAsTheOutwardOne) {
  RenderSettings settings = small(4, true);
  settings.width = 160;
  settings.height = 120;
  RenderScene scene;
  RenderMesh outward = test::make_icosphere({0.0f, 0.5f, 0.0f}, 0.5f, 3, {0.8f, 0.6f, 0.4f});
  outward.indices.resize(outward.indices.size() - 3);  // open: nothing may cull its back faces
  RenderMesh inward = outward;
  for (size_t t = 0; t < inward.indices.size(); t += 3) std::swap(inward.indices[t + 1], inward.indices[t + 2]);
  const Camera camera = frame_bounding_sphere({0.0, 0.5, 0.0}, 0.8, 30.0, 20.0, 40.0, 160.0 / 120.0);
  scene.meshes = {outward};
  const Image expected = Renderer(settings).render(scene, camera);
  scene.meshes = {inward};
  const Image actual = Renderer(settings).render(scene, camera);
  const ImageComparison d = compare_images(actual, expected, 2.0 / 255.0);
  std::cout << "inward against outward: " << 100.0 * d.failing_fraction << " % of pixels off by > 2/255, max "
            << d.max_difference << "\n";
  EXPECT_LT(d.failing_fraction, 0.001);
}

TEST(Renderer, OverATransparentBackgroundTheGroundCatchesOnlyTheShadow) {
  RenderScene scene;
  scene.meshes = {test::make_box({0.0f, 0.5f, 0.0f}, {1.0f, 1.0f, 1.0f}, {0.8f, 0.8f, 0.8f})};
  Camera camera;
  camera.eye = {0.0, 6.0, 0.01};  // looking down: the whole shadow is in view
  camera.target = {0.0, 0.0, 0.0};
  RenderSettings settings = small(4, true);
  settings.transparent_background = true;
  // Black pixels with some coverage: the shadow laid over nothing.
  auto shadow_pixels = [&](const Image& image) {
    int count = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const auto p = at(image, x, y);
        count += p[3] > 40 && p[3] < 255 && p[0] == 0 && p[1] == 0 && p[2] == 0;
      }
    return count;
  };
  const Image caught = Renderer(settings).render(scene, camera);
  std::cout << "shadow pixels caught: " << shadow_pixels(caught) << "\n";
  EXPECT_GT(shadow_pixels(caught), 150);
  // No floor colour, no grid: away from the box and its shadow, nothing at all.
  EXPECT_EQ(at(caught, 2, 2)[3], 0);
  EXPECT_EQ(at(caught, 93, 61)[3], 0);
  settings.ground = false;  // no ground drawn: no shadow on it either
  EXPECT_EQ(shadow_pixels(Renderer(settings).render(scene, camera)), 0);
}

TEST(Renderer, FloorFollowsGroundHeightAndToggles) {
  const RenderSettings settings = small(0);
  Renderer renderer(settings);
  RenderScene scene;
  scene.meshes = {test::make_box({0.0f, 0.5f, 0.0f}, {1.0f, 1.0f, 1.0f}, {0.8f, 0.8f, 0.8f})};
  const Camera camera = studio_camera(settings);
  const Image base = renderer.render(scene, camera);
  scene.ground_height = -0.5f;
  const Image lowered = renderer.render(scene, camera);
  scene.grid = false;
  const Image no_grid = renderer.render(scene, camera);
  scene.ground = false;
  const Image no_floor = renderer.render(scene, camera);
  EXPECT_NE(base.rgba, lowered.rgba);
  EXPECT_NE(lowered.rgba, no_grid.rgba);
  // Without a floor the bottom corner shows the background.
  EXPECT_EQ(at(no_floor, 0, 63), (std::array<int, 4>{0x1d, 0x21, 0x27, 255}));
  EXPECT_NE(at(base, 0, 63), (std::array<int, 4>{0x1d, 0x21, 0x27, 255}));
}

TEST(Renderer, TheFloorHidesWhatIsOnItsFarSideFromAboveAndFromBelow) {
  // Red-dominant pixels: the box showing (the floor and background are grey-blue).
  auto red_pixels = [](const Image& image) {
    int count = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const auto p = at(image, x, y);
        count += p[0] > p[1] + 40 && p[0] > p[2] + 40;
      }
    return count;
  };
  const Rgb red = {0.9f, 0.1f, 0.1f};
  for (int msaa : {0, 4}) {
    // The unit box wholly on the side of the floor away from the eye, or
    // resting on it (its bottom face in the floor's plane) seen from below.
    for (const auto& [eye_height, box_height] : {std::pair{4.0f, -0.7f}, {-4.0f, 0.7f}, {-4.0f, 0.5f}}) {
      RenderScene scene;
      scene.meshes = {test::make_box({0.3f, box_height, 0.0f}, {1.0f, 1.0f, 1.0f}, red)};
      Camera camera;
      camera.eye = {0.5, eye_height, 3.0};
      camera.target = {0.0, 0.0, 0.0};
      const RenderSettings settings = small(msaa, true);
      const int hidden = red_pixels(Renderer(settings).render(scene, camera));
      scene.ground = false;
      const int shown = red_pixels(Renderer(settings).render(scene, camera));
      std::cout << "msaa " << msaa << ", eye at height " << eye_height << ", box at " << box_height << ": " << hidden
                << " red pixels with the floor, " << shown << " without\n";
      EXPECT_EQ(hidden, 0);
      EXPECT_GT(shown, 200);
    }
  }
}

TEST(Renderer, TheShadowMapIsRedrawnOnlyWhenWhatItSeesChanged) {
  const RenderSettings settings = small(4, true);
  Renderer renderer(settings);
  // Two tall posts fix the scene's bounds (and so the shadow map's fit); a
  // small box between them moves and hides without changing those bounds.
  RenderScene scene;
  scene.meshes = {test::make_box({-0.8f, 0.5f, 0.0f}, {0.2f, 1.0f, 1.0f}, {0.8f, 0.8f, 0.8f}),
                  test::make_box({0.8f, 0.5f, 0.0f}, {0.2f, 1.0f, 1.0f}, {0.8f, 0.8f, 0.8f}),
                  test::make_box({0.0f, 0.2f, 0.0f}, {0.3f, 0.3f, 0.3f}, {0.8f, 0.3f, 0.2f})};
  const Camera camera = studio_camera(settings);
  const Image first = renderer.render(scene, camera);
  EXPECT_EQ(renderer.shadow_passes(), 1u);
  // Nothing moved: the map is reused, and the frame is the same.
  EXPECT_EQ(renderer.render(scene, camera).rgba, first.rgba);
  EXPECT_EQ(renderer.shadow_passes(), 1u);
  // The small box moved within the bounds: redrawn, and the frame is what a
  // fresh renderer draws.
  scene.meshes[2] = test::make_box({0.0f, 0.2f, 0.3f}, {0.3f, 0.3f, 0.3f}, {0.8f, 0.3f, 0.2f});
  const Image moved = renderer.render(scene, camera);
  EXPECT_EQ(renderer.shadow_passes(), 2u);
  EXPECT_EQ(moved.rgba, Renderer(settings).render(scene, camera).rgba);
  EXPECT_NE(moved.rgba, first.rgba);
  // The small box hidden (opacity 0) no longer casts: redrawn.
  scene.meshes[2].opacity = 0.0f;
  EXPECT_EQ(renderer.render(scene, camera).rgba, Renderer(settings).render(scene, camera).rgba);
  EXPECT_EQ(renderer.shadow_passes(), 3u);
  // The camera turned, and the studio's key light with it: redrawn.
  const Camera turned = frame_bounding_sphere({0.0, 0.5, 0.0}, 1.6, 75.0, 20.0, 40.0, 96.0 / 64.0);
  EXPECT_EQ(renderer.render(scene, turned).rgba, Renderer(settings).render(scene, turned).rgba);
  EXPECT_EQ(renderer.shadow_passes(), 4u);
}

TEST(Renderer, AmbientOcclusionDarkensOnlyWhereABodyMeetsTheFloor) {
  // A box standing on the floor, seen from above at an angle, without the
  // key's shadow so that only the occlusion differs.
  RenderSettings settings = small(0, false);
  settings.width = 128;
  settings.height = 128;
  RenderScene scene;
  scene.grid = false;
  scene.meshes = {test::make_box({0.0f, 0.25f, 0.0f}, {0.5f, 0.5f, 0.5f}, {0.8f, 0.8f, 0.8f})};
  Camera camera;
  camera.eye = {0.0, 2.5, 1.5};
  camera.target = {0.0, 0.0, 0.0};
  const Image open = Renderer(settings).render(scene, camera);
  settings.ambient_occlusion = true;
  const Image occluded = Renderer(settings).render(scene, camera);
  // The box's top face, facing the sky with nothing above it, and the floor
  // far from the box are as they were (to the last bit's rounding); the floor
  // along the box's base is darker.
  for (const auto& [x, y] : {std::pair{64, 40}, std::pair{4, 124}}) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(at(occluded, x, y)[k], at(open, x, y)[k], 1) << x << "," << y;
  }
  int darker = 0, brighter = 0;
  for (size_t i = 0; i < open.rgba.size(); i += 4) {
    darker += occluded.rgba[i + 1] + 2 < open.rgba[i + 1];
    brighter += occluded.rgba[i + 1] > open.rgba[i + 1] + 1;
  }
  std::cout << "pixels darkened by occlusion: " << darker << " of " << open.rgba.size() / 4 << "\n";
  EXPECT_GT(darker, 40);
  EXPECT_EQ(brighter, 0);  // occlusion never adds light
  // The open floor beside the box, more than 0.3 m from it (the occlusion
  // reaches 6 cm here), is untouched: a flat floor occludes nothing itself.
  for (int y = 0; y < 128; ++y) {
    for (int x : {0, 8, 16, 24, 103, 111, 119, 127}) {
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(at(occluded, x, y)[k], at(open, x, y)[k], 1) << x << "," << y;
    }
  }
  // Determinism holds with it too.
  EXPECT_EQ(Renderer(settings).render(scene, camera).rgba, occluded.rgba);
  // An odd frame size: the occlusion stays on the box's base, not shifted a
  // pixel off it (the half-size pass covers the frame exactly).
  settings.width = 127;
  settings.height = 127;
  const Image odd = Renderer(settings).render(scene, camera);
  settings.ambient_occlusion = false;
  const Image odd_open = Renderer(settings).render(scene, camera);
  int odd_darker = 0;
  for (size_t i = 0; i < odd.rgba.size(); i += 4) odd_darker += odd.rgba[i + 1] + 2 < odd_open.rgba[i + 1];
  EXPECT_NEAR(odd_darker, darker, darker / 4);
}

TEST(Renderer, RejectsADegenerateCamera) {
  Renderer renderer(small(0));
  Camera camera = front_camera();
  camera.target = camera.eye;
  EXPECT_THROW(renderer.render(RenderScene{}, camera), Error);
  camera = front_camera();
  camera.fov_y_degrees = 180.0;
  EXPECT_THROW(renderer.render(RenderScene{}, camera), Error);
}

}  // namespace
}  // namespace recoil::render
