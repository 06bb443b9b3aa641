#pragma once
// Renderer: draws a RenderScene from a Camera into an RGBA8 Image with a
// film-style studio look: three-point lighting, a
// PCF-shadowed key light, a fading ground with a soft grid, smooth normals
// recomputed each frame, per-mesh colour and opacity (transparent meshes
// blended back to front), MSAA, sRGB-correct output.
// Owns its OpenGL context and every GL object, reused across frames; the same
// scene, camera and settings give identical bytes.
#include <cstddef>
#include <memory>

#include "render/camera.h"
#include "render/gl_backend.h"
#include "render/image.h"
#include "render/render_scene.h"

namespace recoil::render {

struct RenderSettings {
  int width = 1280;
  int height = 720;
  int msaa = 4;  // samples per pixel: 0 (off), 2 or 4
  bool shadows = true;
  // Screen-space ambient occlusion (ambient_occlusion.h): creases and contacts darken.
  bool ambient_occlusion = false;
  Rgb background = {0x1d / 255.0f, 0x21 / 255.0f, 0x27 / 255.0f};  // sRGB #1d2127
  bool transparent_background = false;  // alpha 0 where nothing (not even the floor) is drawn
  bool wireframe = false;               // dark triangle edges over the shaded meshes
  GlBackend gl = GlBackend::automatic;  // which library gives the OpenGL context (context.h)
  // The scene's ground plane is drawn (over a transparent background as a
  // shadow catcher: the shadows alone); false: not at all, shadows on it neither.
  bool ground = true;
};

class Renderer {
 public:
  // Creates the OpenGL context (throws recoil::Error without OSMesa or EGL) and the
  // framebuffers. Throws RefusedSetting (refused_setting.h, bad input) for a
  // size or msaa the settings or the driver do not allow.
  explicit Renderer(const RenderSettings& settings);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  Image render(const RenderScene& scene, const Camera& camera);
  // The same, reusing `image`'s storage (a turntable renders hundreds of frames).
  void render(const RenderScene& scene, const Camera& camera, Image& image);

  const RenderSettings& settings() const { return m_settings; }
  // Times the key light's shadow map was drawn: once per frame at most, and
  // not again while the meshes and the light are those it was drawn from.
  std::size_t shadow_passes() const;
  // The backend in use (never automatic) and its GL_RENDERER string.
  GlBackend backend() const;
  std::string gl_renderer();

 private:
  struct Impl;
  RenderSettings m_settings;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace recoil::render
