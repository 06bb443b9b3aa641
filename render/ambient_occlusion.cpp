#include "render/ambient_occlusion.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "render/shaders.h"

namespace recoil::render {
namespace {

gl::Texture make_texture(int width, int height, GLenum internal, GLenum format, GLenum type, GLint filter) {
  gl::Texture texture = gl::Texture::create();
  glBindTexture(GL_TEXTURE_2D, texture.get());
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), width, height, 0, format, type, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

gl::Framebuffer make_target(GLenum attachment, const gl::Texture& texture) {
  gl::Framebuffer target = gl::Framebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, target.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture.get(), 0);
  if (attachment == GL_DEPTH_ATTACHMENT) {
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
  }
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error(ErrorKind::internal, "the OpenGL driver refused a render target for ambient occlusion");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return target;
}

}  // namespace

AmbientOcclusion::AmbientOcclusion(int frame_width, int frame_height)
    : m_frame_width(frame_width),
      m_frame_height(frame_height),
      m_width(std::max(1, (frame_width + kScale - 1) / kScale)),
      m_height(std::max(1, (frame_height + kScale - 1) / kScale)),
      m_depth(make_texture(m_width, m_height, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, GL_NEAREST)),
      m_raw(make_texture(m_width, m_height, GL_R8, GL_RED, GL_UNSIGNED_BYTE, GL_LINEAR)),
      m_blurred(make_texture(m_width, m_height, GL_R8, GL_RED, GL_UNSIGNED_BYTE, GL_LINEAR)),
      m_depth_target(make_target(GL_DEPTH_ATTACHMENT, m_depth)),
      m_raw_target(make_target(GL_COLOR_ATTACHMENT0, m_raw)),
      m_blurred_target(make_target(GL_COLOR_ATTACHMENT0, m_blurred)),
      m_empty(gl::VertexArray::create()),
      m_occlusion("ambient occlusion", shaders::fullscreen_vertex(), shaders::occlusion_fragment()),
      m_blur("ambient occlusion blur", shaders::fullscreen_vertex(), shaders::box_blur_fragment()) {}

ScreenRect AmbientOcclusion::region_around(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                           const Eigen::Matrix4f& view_projection) const {
  return screen_rect(lo, hi, view_projection, m_width, m_height, 2);
}

void AmbientOcclusion::begin_depth(const ScreenRect& region) {
  glViewport(0, 0, m_width, m_height);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  for (const gl::Framebuffer* target : {&m_raw_target, &m_blurred_target}) {
    glBindFramebuffer(GL_FRAMEBUFFER, target->get());
    glClear(GL_COLOR_BUFFER_BIT);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, m_depth_target.get());
  glClear(GL_DEPTH_BUFFER_BIT);
  scissor_to(region);
}

void AmbientOcclusion::resolve(const Eigen::Matrix4f& projection, float radius) {
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(m_empty.get());
  glActiveTexture(GL_TEXTURE0);

  glBindFramebuffer(GL_FRAMEBUFFER, m_raw_target.get());
  m_occlusion.use();
  glBindTexture(GL_TEXTURE_2D, m_depth.get());
  glUniform1i(m_occlusion.location("u_depth"), 0);
  glUniformMatrix4fv(m_occlusion.location("u_projection"), 1, GL_FALSE, projection.data());
  glUniform1f(m_occlusion.location("u_radius"), radius);
  glUniform2f(m_occlusion.location("u_size"), static_cast<float>(m_width), static_cast<float>(m_height));
  glDrawArrays(GL_TRIANGLES, 0, 3);

  glBindFramebuffer(GL_FRAMEBUFFER, m_blurred_target.get());
  m_blur.use();
  glBindTexture(GL_TEXTURE_2D, m_raw.get());
  glUniform1i(m_blur.location("u_source"), 0);
  glUniform2f(m_blur.location("u_texel"), 1.0f / static_cast<float>(m_width), 1.0f / static_cast<float>(m_height));
  glDrawArrays(GL_TRIANGLES, 0, 3);

  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
}

void AmbientOcclusion::bind_texture(GLenum unit) const {
  glActiveTexture(unit);
  glBindTexture(GL_TEXTURE_2D, m_blurred.get());
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace recoil::render
