#include "render/shadow_map.h"

#include "core/check.h"
#include "core/error.h"
#include "render/camera.h"

namespace recoil::render {

ShadowMap::ShadowMap(int size)
    : m_size(size), m_depth(gl::Texture::create()), m_framebuffer(gl::Framebuffer::create()) {
  glBindTexture(GL_TEXTURE_2D, m_depth.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
               nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Outside the light's box nothing casts: the border reads as depth 1, lit.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth.get(), 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error(ErrorKind::internal, "the OpenGL driver refused a " + std::to_string(size) +
                                         "^2 depth texture for shadows (Mesa llvmpipe expected)");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Eigen::Matrix4f ShadowMap::begin(const Eigen::Vector3d& center, double radius, const Eigen::Vector3d& to_light) {
  RECOIL_CHECK(radius > 0, "radius=" << radius);
  // Stand off by two radii so the casters sit well inside [near, far]; the far
  // plane reaches past the sphere so receivers below it (the ground) compare
  // against real depths. Receivers beyond it clamp to 1 and stay lit where
  // nothing was drawn (cleared depth 1).
  Camera light;
  light.target = center;
  light.eye = center + 2.0 * radius * to_light;
  light.up = std::abs(to_light.y()) > 0.99 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
  const double near_plane = radius;
  const double far_plane = 6.0 * radius;
  Eigen::Matrix4d ortho = Eigen::Matrix4d::Identity();
  ortho(0, 0) = 1.0 / radius;
  ortho(1, 1) = 1.0 / radius;
  ortho(2, 2) = -2.0 / (far_plane - near_plane);
  ortho(2, 3) = -(far_plane + near_plane) / (far_plane - near_plane);
  const Eigen::Matrix4d clip = ortho * light.view_matrix();
  Eigen::Matrix4d bias = Eigen::Matrix4d::Identity();
  bias.block<3, 3>(0, 0) *= 0.5;
  bias.block<3, 1>(0, 3).setConstant(0.5);
  m_texture_matrix = (bias * clip).cast<float>();
  m_texel_world = 2.0 * radius / m_size;

  glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.get());
  glViewport(0, 0, m_size, m_size);
  return clip.cast<float>();
}

void ShadowMap::bind_texture(GLenum unit) const {
  glActiveTexture(unit);
  glBindTexture(GL_TEXTURE_2D, m_depth.get());
}

}  // namespace recoil::render
