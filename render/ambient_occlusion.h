#pragma once
// AmbientOcclusion: screen-space ambient occlusion at half the frame's size.
// The opaque meshes and the floor are drawn depth-only into a texture; a
// full-screen pass looks up the surface at 12 taps on a spiral around each
// pixel, out to a reach in metres, and each surface point found closes the
// pixel's hemisphere by how far it rises above the pixel's tangent plane (so
// a plane closes nothing); a 4x4 box blur (four bilinear taps) evens out the
// 4x4 pattern the spiral is turned by. The lighting passes then read one value
// per pixel, which dims the diffuse light in creases and where a body meets
// the floor. Only the part of the frame near the meshes is computed.
#include <Eigen/Core>

#include "render/gl_objects.h"
#include "render/screen_rect.h"
#include "render/shader_program.h"

namespace recoil::render {

class AmbientOcclusion {
 public:
  // Frame pixels per occlusion pixel, each way.
  static constexpr int kScale = 2;

  AmbientOcclusion(int frame_width, int frame_height);

  // The pixels of this pass where the box [lo, hi] (metres) can show, seen
  // through `view_projection` (world to clip, 4 by 4), plus the blur's two
  // pixels; all of them when a corner is behind the eye.
  ScreenRect region_around(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                           const Eigen::Matrix4f& view_projection) const;

  // Binds the depth target, viewport set and depth cleared, for depth-only
  // draws limited to `region`; outside it everything stays open (1). It
  // leaves the scissor test on, and the clear colour white, until resolve().
  void begin_depth(const ScreenRect& region);
  // Turns the depth drawn into occlusion, in the region only, and turns the
  // scissor test off again. `projection`:
  // the frame's view to clip (4 by 4, a symmetric perspective); `radius`: how
  // far the occlusion reaches, metres.
  void resolve(const Eigen::Matrix4f& projection, float radius);
  // The visibility texture (R: 1 open, 0 enclosed), bilinear.
  void bind_texture(GLenum unit) const;
  int width() const { return m_width; }
  int height() const { return m_height; }
  // The frame it covers, which the depth pass stretches over its own size.
  int frame_width() const { return m_frame_width; }
  int frame_height() const { return m_frame_height; }

 private:
  int m_frame_width, m_frame_height;
  int m_width, m_height;
  gl::Texture m_depth;
  gl::Texture m_raw;      // occlusion before the blur
  gl::Texture m_blurred;  // what the lighting reads
  gl::Framebuffer m_depth_target;
  gl::Framebuffer m_raw_target;
  gl::Framebuffer m_blurred_target;
  gl::VertexArray m_empty;  // the full-screen triangle comes from gl_VertexID
  ShaderProgram m_occlusion;
  ShaderProgram m_blur;
};

}  // namespace recoil::render
