#pragma once
// AmbientOcclusion: screen-space ambient occlusion at half the frame's size.
// The opaque meshes and the floor are drawn depth-only into a texture; a
// full-screen pass tests 12 fixed points of the hemisphere above each pixel's
// surface against that depth; a 4x4 box blur (four bilinear taps) evens out
// the 4x4 rotation pattern of those points. The lighting passes then read one
// value per pixel, which dims the ambient and fill light in creases and
// where a body meets the floor.
#include <Eigen/Core>

#include "render/gl_objects.h"
#include "render/shader_program.h"

namespace recoil::render {

class AmbientOcclusion {
 public:
  AmbientOcclusion(int frame_width, int frame_height);

  // Binds the depth target, viewport set and depth cleared, for depth-only draws.
  void begin_depth();
  // Turns the depth drawn into occlusion. `projection`: the frame's view to
  // clip (4 by 4); `radius`: how far the hemisphere reaches, metres.
  void resolve(const Eigen::Matrix4f& projection, float radius);
  // The visibility texture (R: 1 open, 0 enclosed), bilinear.
  void bind_texture(GLenum unit) const;
  int width() const { return m_width; }
  int height() const { return m_height; }

 private:
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
