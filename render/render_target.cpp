#include "render/render_target.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "render/refused_setting.h"
#include "render/shaders.h"

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

// The colour texture of the meshes' layer, sampled by texel in the lay-over pass.
void texture_storage(GLuint texture, int samples, int width, int height) {
  if (samples > 0) {
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, texture);
    glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, GL_SRGB8_ALPHA8, width, height, GL_TRUE);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
  } else {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
}

}  // namespace

RenderTarget::RenderTarget(int width, int height, int msaa)
    : m_width(width),
      m_height(height),
      m_msaa(msaa),
      m_mesh_color(gl::Texture::create()),
      m_mesh_depth(gl::Renderbuffer::create()),
      m_meshes(gl::Framebuffer::create()),
      m_frame_color(gl::Renderbuffer::create()),
      m_frame(gl::Framebuffer::create()),
      m_empty(gl::VertexArray::create()),
      m_lay_over("lay meshes over frame", shaders::fullscreen_vertex(), shaders::lay_over_fragment(msaa)) {
  GLint max_size = 0, max_samples = 0, max_color_samples = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &max_color_samples);
  max_samples = std::min(max_samples, max_color_samples);
  if (width > max_size || height > max_size) {
    throw RefusedSetting("resolution", "render resolution " + std::to_string(width) + "x" + std::to_string(height) +
                    " exceeds the OpenGL driver's limit of " + std::to_string(max_size));
  }
  if (msaa > max_samples) {
    throw RefusedSetting("msaa", "render msaa " + std::to_string(msaa) + " exceeds the OpenGL driver's limit of " +
                    std::to_string(max_samples) + " samples");
  }
  texture_storage(m_mesh_color.get(), msaa, width, height);
  storage(m_mesh_depth.get(), msaa, GL_DEPTH_COMPONENT24, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, m_meshes.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, msaa > 0 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D,
                         m_mesh_color.get(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_mesh_depth.get());
  check_complete(msaa > 0 ? "multisampled colour and depth" : "colour and depth", width, height, msaa);
  if (msaa > 0) {
    // A driver may round the count up (llvmpipe offers 4 only): the image
    // would then be --msaa 4's, so the request is refused, not changed.
    GLint samples = 0;
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, m_mesh_color.get());
    glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &samples);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    if (samples != msaa) {
      const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
      throw RefusedSetting("msaa", "render msaa " + std::to_string(msaa) + ": this OpenGL driver (" +
                      std::string(renderer ? renderer : "unknown") + ") draws " + std::to_string(samples) +
                      " samples when asked for " + std::to_string(msaa) + "; use msaa 0" +
                      (samples == 2 || samples == 4 ? " or " + std::to_string(samples) : std::string()));
    }
  }
  storage(m_frame_color.get(), 0, GL_SRGB8_ALPHA8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, m_frame.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_frame_color.get());
  check_complete("frame", width, height, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTarget::bind_frame() const {
  glBindFramebuffer(GL_FRAMEBUFFER, m_frame.get());
  glViewport(0, 0, m_width, m_height);
}

void RenderTarget::begin_meshes(const ScreenRect& rect) {
  glBindFramebuffer(GL_FRAMEBUFFER, m_meshes.get());
  glViewport(0, 0, m_width, m_height);
  scissor_to(rect);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void RenderTarget::lay_meshes_over_frame(const ScreenRect& rect, GLenum unit) {
  bind_frame();
  scissor_to(rect);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied colour, linear with GL_FRAMEBUFFER_SRGB
  glActiveTexture(unit);
  glBindTexture(m_msaa > 0 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, m_mesh_color.get());
  m_lay_over.use();
  glUniform1i(m_lay_over.location("u_layer"), static_cast<GLint>(unit - GL_TEXTURE0));
  glBindVertexArray(m_empty.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
}

void RenderTarget::read(Image& image) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m_frame.get());
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
