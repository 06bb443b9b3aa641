#include "render/ground.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace recoil::render {
namespace {

constexpr std::size_t kCellIndices = 6;
constexpr std::size_t kSurroundIndices = 48;

}  // namespace

GroundLayout ground_layout(double center_x, double center_z, double radius, double height) {
  GroundLayout layout;
  layout.center_x = center_x;
  layout.center_z = center_z;
  layout.height = height;
  layout.fade_start = 2.0 * radius;
  layout.fade_end = 6.0 * radius;
  // A power of ten near the scene's size: a 1 m object gets 1 m major and 10 cm minor lines.
  layout.grid_spacing = std::pow(10.0, std::floor(std::log10(2.0 * radius)));
  layout.cell = {center_x - layout.fade_end, center_x + layout.fade_end, center_z - layout.fade_end,
                 center_z + layout.fade_end};
  return layout;
}

FloorRect FloorRect::united(const FloorRect& other) const {
  return {std::min(x0, other.x0), std::max(x1, other.x1), std::min(z0, other.z0), std::max(z1, other.z1)};
}

std::optional<FloorRect> shadow_reach(double height, const Eigen::Vector3d& center, double radius,
                                      const Eigen::Vector3d& to_light, double reach) {
  // A floor point is shadowed only if the ray from it to the light meets the
  // sphere: the floor's shadow of the sphere is an ellipse around the centre's
  // projection along the light, of half axes r and r / sin(elevation), so a
  // square of half size r / sin(elevation) holds it.
  const double sine = to_light.y();
  if (!(sine > 0.05)) return std::nullopt;
  const double drop = (center.y() - height) / sine;
  const double x = center.x() - to_light.x() * drop;
  const double z = center.z() - to_light.z() * drop;
  const double half = (radius + reach) / sine;
  return FloorRect{x - half, x + half, z - half, z + half};
}

FloorRect near_reach(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double reach) {
  return {lo.x() - reach, hi.x() + reach, lo.z() - reach, hi.z() + reach};
}

void set_cell(GroundLayout& layout, const FloorRect& cell) {
  const double x0 = layout.center_x - layout.fade_end, x1 = layout.center_x + layout.fade_end;
  const double z0 = layout.center_z - layout.fade_end, z1 = layout.center_z + layout.fade_end;
  layout.cell = {std::clamp(cell.x0, x0, x1), std::clamp(cell.x1, x0, x1), std::clamp(cell.z0, z0, z1),
                 std::clamp(cell.z1, z0, z1)};
}

Ground::Ground()
    : m_vertex_array(gl::VertexArray::create()), m_corners(gl::Buffer::create()), m_elements(gl::Buffer::create()) {
  glBindVertexArray(m_vertex_array.get());
  glBindBuffer(GL_ARRAY_BUFFER, m_corners.get());
  glBufferData(GL_ARRAY_BUFFER, 48 * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  // Cells share their corners, so the cut leaves no cracks. Each cell is two
  // triangles, counter-clockwise seen from above (+Y).
  std::array<std::uint32_t, kCellIndices + kSurroundIndices> indices{};
  std::size_t next = kCellIndices;
  for (std::uint32_t row = 0; row < 3; ++row) {
    for (std::uint32_t column = 0; column < 3; ++column) {
      const std::uint32_t a = 4 * row + column;  // (x_i, z_j): vertex 4 j + i
      const std::array<std::uint32_t, kCellIndices> cell = {a, a + 4, a + 1, a + 1, a + 4, a + 5};
      const bool middle = row == 1 && column == 1;
      std::copy(cell.begin(), cell.end(), indices.begin() + static_cast<std::ptrdiff_t>(middle ? 0 : next));
      if (!middle) next += kCellIndices;
    }
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_elements.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(indices), indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

void Ground::bind(const GroundLayout& layout) {
  glBindVertexArray(m_vertex_array.get());
  const bool same = m_has_upload && layout.center_x == m_uploaded.center_x &&
                    layout.center_z == m_uploaded.center_z && layout.height == m_uploaded.height &&
                    layout.fade_end == m_uploaded.fade_end && layout.cell == m_uploaded.cell;
  if (same) return;
  const std::array<float, 4> xs = {static_cast<float>(layout.center_x - layout.fade_end),
                                   static_cast<float>(layout.cell.x0), static_cast<float>(layout.cell.x1),
                                   static_cast<float>(layout.center_x + layout.fade_end)};
  const std::array<float, 4> zs = {static_cast<float>(layout.center_z - layout.fade_end),
                                   static_cast<float>(layout.cell.z0), static_cast<float>(layout.cell.z1),
                                   static_cast<float>(layout.center_z + layout.fade_end)};
  std::array<float, 48> corners{};
  for (std::size_t j = 0; j < 4; ++j) {
    for (std::size_t i = 0; i < 4; ++i) {
      corners[3 * (4 * j + i) + 0] = xs[i];
      corners[3 * (4 * j + i) + 1] = static_cast<float>(layout.height);
      corners[3 * (4 * j + i) + 2] = zs[j];
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, m_corners.get());
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(corners), corners.data());
  m_uploaded = layout;
  m_has_upload = true;
}

void Ground::draw(const GroundLayout& layout) {
  bind(layout);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(kCellIndices + kSurroundIndices), GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

void Ground::draw_cell(const GroundLayout& layout) {
  bind(layout);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(kCellIndices), GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

void Ground::draw_surround(const GroundLayout& layout) {
  bind(layout);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(kSurroundIndices), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(kCellIndices * sizeof(std::uint32_t)));
  glBindVertexArray(0);
}

}  // namespace recoil::render
