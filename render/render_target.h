#pragma once
// RenderTarget: where a frame is drawn, as two sRGB layers (blending and
// sample averaging happen on linear values; the stored bytes are sRGB):
// - the meshes' layer, multisampled when msaa > 0, with depth; cleared to
//   transparent and drawn only within the rectangle the meshes can cover;
// - the frame: one sample per pixel and no depth; the background and the
//   ground are drawn into it, the meshes' layer is laid over it
//   (premultiplied, its samples averaged) and it is what is read back.
// The ground, most of a frame's pixels, is thus shaded and stored once per
// pixel instead of once per sample; only the meshes' edges need samples.
#include "render/gl_objects.h"
#include "render/image.h"
#include "render/screen_rect.h"
#include "render/shader_program.h"

namespace recoil::render {

class RenderTarget {
 public:
  // msaa: 0 (off), 2 or 4 samples.
  RenderTarget(int width, int height, int msaa);

  // Binds the frame layer and sets the viewport.
  void bind_frame() const;
  // Binds the meshes' layer, clears it (transparent, far) within `rect` and
  // leaves the scissor test on there.
  void begin_meshes(const ScreenRect& rect);
  // Lays the meshes' layer over the frame layer within `rect`, through
  // texture `unit`; leaves the frame layer bound, blending and scissor off.
  void lay_meshes_over_frame(const ScreenRect& rect, GLenum unit);
  // Reads the frame layer into `image`, top row first.
  void read(Image& image);

  int width() const { return m_width; }
  int height() const { return m_height; }

 private:
  int m_width;
  int m_height;
  int m_msaa;
  gl::Texture m_mesh_color;  // GL_TEXTURE_2D_MULTISAMPLE when msaa > 0, else GL_TEXTURE_2D
  gl::Renderbuffer m_mesh_depth;
  gl::Framebuffer m_meshes;
  gl::Renderbuffer m_frame_color;
  gl::Framebuffer m_frame;
  gl::VertexArray m_empty;  // the full-screen triangle comes from gl_VertexID
  ShaderProgram m_lay_over;
};

}  // namespace recoil::render
