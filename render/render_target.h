#pragma once
// RenderTarget: where a frame is drawn. An sRGB colour buffer (so blending
// and MSAA averaging happen on linear values and the stored bytes are
// sRGB-encoded) plus depth; multisampled when msaa > 0, then resolved by a
// blit into a single-sample buffer that is read back.
#include "render/gl_objects.h"
#include "render/image.h"

namespace recoil::render {

class RenderTarget {
 public:
  // msaa: 0 (off), 2 or 4 samples.
  RenderTarget(int width, int height, int msaa);

  // Binds the framebuffer to draw into and sets the viewport.
  void bind_for_drawing() const;
  // Resolves the samples (if any) and reads the pixels into `image`, top row first.
  void read(Image& image);

  int width() const { return m_width; }
  int height() const { return m_height; }

 private:
  int m_width;
  int m_height;
  int m_msaa;
  gl::Renderbuffer m_draw_color;
  gl::Renderbuffer m_draw_depth;
  gl::Framebuffer m_draw;
  gl::Renderbuffer m_resolve_color;  // only with msaa
  gl::Framebuffer m_resolve;
};

}  // namespace recoil::render
