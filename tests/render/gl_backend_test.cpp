// The two OpenGL backends: OSMesa and EGL (surfaceless) draw the same frames
// on llvmpipe, byte for byte, and may live side by side in one process.
#include <gtest/gtest.h>

#include "render/renderer.h"
#include "tests/render/test_meshes.h"

namespace recoil::render {
namespace {

RenderSettings settings_for(GlBackend backend) {
  RenderSettings settings;
  settings.width = 160;
  settings.height = 96;
  settings.msaa = 4;
  settings.shadows = true;
  settings.gl = backend;
  return settings;
}

TEST(GlBackend, OsmesaAndEglDrawIdenticalFrames) {
  const Camera camera = frame_bounding_sphere({0.0, 0.5, 0.0}, 1.6, 30.0, 20.0, 40.0, 160.0 / 96.0);
  Renderer osmesa(settings_for(GlBackend::osmesa));
  Renderer egl(settings_for(GlBackend::egl));
  EXPECT_EQ(osmesa.backend(), GlBackend::osmesa);
  EXPECT_EQ(egl.backend(), GlBackend::egl);
  std::cout << "osmesa: " << osmesa.gl_renderer() << "; egl: " << egl.gl_renderer() << "\n";
  // Interleaved, so each frame switches the thread from one backend to the other.
  for (int frame = 0; frame < 2; ++frame) {
    const Image a = osmesa.render(test::studio_scene(), camera);
    const Image b = egl.render(test::studio_scene(), camera);
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    EXPECT_TRUE(a.rgba == b.rgba) << "frame " << frame;
  }
}

TEST(GlBackend, AutomaticPicksOsmesaWhereItWorks) {
  EXPECT_EQ(Renderer(settings_for(GlBackend::automatic)).backend(), GlBackend::osmesa);
}

TEST(GlBackend, NamesRoundTrip) {
  for (GlBackend b : {GlBackend::automatic, GlBackend::osmesa, GlBackend::egl})
    EXPECT_EQ(parse_gl_backend(gl_backend_name(b)), b);
  EXPECT_FALSE(parse_gl_backend("vulkan"));
}

}  // namespace
}  // namespace recoil::render
