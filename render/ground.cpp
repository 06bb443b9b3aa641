#include "render/ground.h"

#include <array>
#include <cmath>

namespace recoil::render {

GroundLayout ground_layout(double center_x, double center_z, double radius, double height) {
  GroundLayout layout;
  layout.center_x = center_x;
  layout.center_z = center_z;
  layout.height = height;
  layout.fade_start = 2.0 * radius;
  layout.fade_end = 6.0 * radius;
  // A power of ten near the scene's size: a 1 m object gets 1 m major and 10 cm minor lines.
  layout.grid_spacing = std::pow(10.0, std::floor(std::log10(2.0 * radius)));
  return layout;
}

Ground::Ground() : m_vertex_array(gl::VertexArray::create()), m_corners(gl::Buffer::create()) {
  glBindVertexArray(m_vertex_array.get());
  glBindBuffer(GL_ARRAY_BUFFER, m_corners.get());
  glBufferData(GL_ARRAY_BUFFER, 12 * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindVertexArray(0);
}

void Ground::draw(const GroundLayout& layout) {
  glBindVertexArray(m_vertex_array.get());
  const bool same = m_has_upload && layout.center_x == m_uploaded.center_x &&
                    layout.center_z == m_uploaded.center_z && layout.height == m_uploaded.height &&
                    layout.fade_end == m_uploaded.fade_end;
  if (!same) {
    const auto x0 = static_cast<float>(layout.center_x - layout.fade_end);
    const auto x1 = static_cast<float>(layout.center_x + layout.fade_end);
    const auto z0 = static_cast<float>(layout.center_z - layout.fade_end);
    const auto z1 = static_cast<float>(layout.center_z + layout.fade_end);
    const auto y = static_cast<float>(layout.height);
    // Triangle strip, counter-clockwise seen from above.
    const std::array<float, 12> corners = {x0, y, z1, x1, y, z1, x0, y, z0, x1, y, z0};
    glBindBuffer(GL_ARRAY_BUFFER, m_corners.get());
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(corners), corners.data());
    m_uploaded = layout;
    m_has_upload = true;
  }
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glBindVertexArray(0);
}

}  // namespace recoil::render
