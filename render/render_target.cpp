#include "render/render_target.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "render/refused_setting.h"

namespace recoil::render {
namespace {

// A framebuffer the driver will not allocate is a request too large for this
// machine's renderer (llvmpipe caps each buffer), so it is the user's to change.
void check_complete(const char* what, int width, int height, int samples) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    const double gib = 8.0 * width * height * std::max(1, samples) / (1024.0 * 1024.0 * 1024.0);
    char size[32];
    std::snprintf(size, sizeof size, "%.1f", gib);
    throw RefusedSetting("resolution", std::string("the OpenGL driver cannot allocate the ") + what + " framebuffer of " +
                    std::to_string(width) + "x" + std::to_string(height) + " pixels at " + std::to_string(samples) +
                    " samples (" + size + " GiB, status " + std::to_string(status) + "); lower the resolution or msaa");
  }
}

void storage(GLuint renderbuffer, int samples, GLenum format, int width, int height) {
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
  if (samples > 0) {
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  } else {
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  }
}

}  // namespace

RenderTarget::RenderTarget(int width, int height, int msaa)
    : m_width(width),
      m_height(height),
      m_msaa(msaa),
      m_draw_color(gl::Renderbuffer::create()),
      m_draw_depth(gl::Renderbuffer::create()),
      m_draw(gl::Framebuffer::create()) {
  GLint max_size = 0, max_samples = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (width > max_size || height > max_size) {
    throw RefusedSetting("resolution", "render resolution " + std::to_string(width) + "x" + std::to_string(height) +
                    " exceeds the OpenGL driver's limit of " + std::to_string(max_size));
  }
  if (msaa > max_samples) {
    throw RefusedSetting("msaa", "render msaa " + std::to_string(msaa) + " exceeds the OpenGL driver's limit of " +
                    std::to_string(max_samples) + " samples");
  }
  storage(m_draw_color.get(), msaa, GL_SRGB8_ALPHA8, width, height);
  storage(m_draw_depth.get(), msaa, GL_DEPTH_COMPONENT24, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, m_draw.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_draw_color.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_draw_depth.get());
  check_complete("multisampled colour and depth", width, height, msaa);
  if (msaa > 0) {
    glBindRenderbuffer(GL_RENDERBUFFER, m_draw_color.get());
    // A driver may round the count up (llvmpipe offers 4 only): the image
    // would then be --msaa 4's, so the request is refused, not changed.
    GLint samples = 0;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &samples);
    if (samples != msaa) {
      const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
      throw RefusedSetting("msaa", "render msaa " + std::to_string(msaa) + ": this OpenGL driver (" +
                      std::string(renderer ? renderer : "unknown") + ") draws " + std::to_string(samples) +
                      " samples when asked for " + std::to_string(msaa) + "; use msaa 0" +
                      (samples == 2 || samples == 4 ? " or " + std::to_string(samples) : std::string()));
    }
    m_resolve_color = gl::Renderbuffer::create();
    m_resolve = gl::Framebuffer::create();
    storage(m_resolve_color.get(), 0, GL_SRGB8_ALPHA8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_resolve.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_resolve_color.get());
    check_complete("resolve", width, height, 0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTarget::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, m_draw.get());
  glViewport(0, 0, m_width, m_height);
}

void RenderTarget::read(Image& image) {
  if (m_msaa > 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_draw.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_resolve.get());
    // With GL_FRAMEBUFFER_SRGB on (as the renderer leaves it), the samples are
    // averaged as linear values, so edges do not darken.
    glBlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_width, m_height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_resolve.get());
  } else {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_draw.get());
  }
  if (image.width != m_width || image.height != m_height) image = Image(m_width, m_height);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // GL's rows run bottom-up; Image (and PNG) want the top row first.
  const std::size_t row = static_cast<std::size_t>(m_width) * 4;
  for (int y = 0; y < m_height / 2; ++y) {
    std::swap_ranges(image.rgba.begin() + static_cast<std::ptrdiff_t>(y * row),
                     image.rgba.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                     image.rgba.begin() + static_cast<std::ptrdiff_t>((m_height - 1 - y) * row));
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

}  // namespace recoil::render
