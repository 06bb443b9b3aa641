#pragma once
// ShadowMap: the key light's depth texture, an orthographic view along the
// light direction fitted to the casters' bounding sphere, sampled with
// hardware depth comparison (GL_LINEAR = 2x2 PCF per tap).
#include <Eigen/Core>

#include "render/gl_objects.h"

namespace recoil::render {

class ShadowMap {
 public:
  // The largest map drawn (texels a side), at 720p and above.
  static constexpr int kLargestSize = 2048;

  explicit ShadowMap(int size);

  // Fits the light's box around the sphere (center, radius) seen along
  // `to_light` (unit, towards the light) and binds the depth framebuffer with
  // the viewport set. Returns the world-to-clip matrix of the light (4 by 4).
  Eigen::Matrix4f begin(const Eigen::Vector3d& center, double radius, const Eigen::Vector3d& to_light);

  // World to shadow-map coordinates in [0,1]^3 (texture s, t and depth).
  const Eigen::Matrix4f& texture_matrix() const { return m_texture_matrix; }
  // One texel in metres, for the receivers' normal offset.
  double texel_world() const { return m_texel_world; }
  int size() const { return m_size; }
  void bind_texture(GLenum unit) const;

 private:
  int m_size;
  gl::Texture m_depth;
  gl::Framebuffer m_framebuffer;
  Eigen::Matrix4f m_texture_matrix = Eigen::Matrix4f::Identity();
  double m_texel_world = 0.0;
};

}  // namespace recoil::render
