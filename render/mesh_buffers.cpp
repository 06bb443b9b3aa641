#include "render/mesh_buffers.h"

#include <algorithm>
#include <numeric>

#include "core/check.h"
#include "render/vertex_normals.h"

namespace recoil::render {

MeshBuffers::MeshBuffers()
    : m_vertex_array(gl::VertexArray::create()),
      m_positions(gl::Buffer::create()),
      m_normals(gl::Buffer::create()),
      m_elements(gl::Buffer::create()),
      m_colors(gl::Buffer::create()),
      m_uvs(gl::Buffer::create()) {
  glBindVertexArray(m_vertex_array.get());
  glBindBuffer(GL_ARRAY_BUFFER, m_positions.get());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, m_normals.get());
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, m_colors.get());
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, m_uvs.get());
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_elements.get());
  glBindVertexArray(0);
}

void MeshBuffers::set_topology(const RenderMesh& mesh) {
  const auto vertex_count = static_cast<std::uint32_t>(mesh.positions.size() / 3);
  const auto worst = std::max_element(mesh.indices.begin(), mesh.indices.end());
  RECOIL_CHECK(worst == mesh.indices.end() || *worst < vertex_count,
               "index " << *worst << " >= vertex count " << vertex_count);
  m_indices = mesh.indices;
  m_look = mesh.look;
  if (mesh.look) {
    set_look(mesh);
  } else {
    m_split = split_creases(mesh.positions, mesh.indices, kCreaseDegrees);
    m_groups.clear();
    m_textures.clear();
    glBindVertexArray(m_vertex_array.get());
    glDisableVertexAttribArray(2);
    glDisableVertexAttribArray(3);
  }
  glBindVertexArray(m_vertex_array.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m_split.indices.size() * sizeof(std::uint32_t)),
               m_split.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

void MeshBuffers::set_look(const RenderMesh& mesh) {
  const RenderLook& look = *mesh.look;
  const size_t faces = mesh.indices.size() / 3;
  RECOIL_CHECK(look.triangle_materials.size() == faces && look.corner_colors.size() == 9 * faces &&
                   (look.corner_uvs.empty() || look.corner_uvs.size() == 6 * faces),
               "look of " << look.triangle_materials.size() << " triangles for " << faces);
  for (std::uint32_t m : look.triangle_materials) RECOIL_CHECK(m < look.materials.size(), "material " << m);
  // Per corner: colour, texture coordinates (only where a texture samples
  // them, so stray UVs split nothing) and material.
  constexpr size_t kStride = 6;
  std::vector<float> keys(kStride * 3 * faces, 0.0f);
  for (size_t c = 0; c < 3 * faces; ++c) {
    const std::uint32_t material = look.triangle_materials[c / 3];
    float* key = keys.data() + kStride * c;
    std::copy_n(look.corner_colors.data() + 3 * c, 3, key);
    if (!look.corner_uvs.empty() && look.materials[material].texture) std::copy_n(look.corner_uvs.data() + 2 * c, 2, key + 3);
    key[5] = static_cast<float>(material);
  }
  const CreaseSplit split = split_creases(mesh.positions, mesh.indices, kCreaseDegrees, keys, kStride);
  const size_t render_vertices = split.source.size();
  std::vector<float> colors(3 * render_vertices, 1.0f), uvs(2 * render_vertices, 0.0f);
  for (size_t c = 0; c < split.indices.size(); ++c) {
    const size_t v = split.indices[c];
    std::copy_n(keys.data() + kStride * c, 3, colors.data() + 3 * v);
    std::copy_n(keys.data() + kStride * c + 3, 2, uvs.data() + 2 * v);
  }
  // Triangles grouped by material, in their own order within a group.
  std::vector<std::uint32_t> order(faces);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return look.triangle_materials[a] < look.triangle_materials[b];
  });
  m_split = split;
  m_split.indices.clear();
  m_groups.clear();
  m_textures.clear();
  std::vector<GLuint> texture_of(look.materials.size(), 0);
  for (std::uint32_t f : order) {
    const std::uint32_t material = look.triangle_materials[f];
    if (m_groups.empty() || m_groups.back().material != &look.materials[material]) {
      Group group;
      group.first = m_split.indices.size();
      group.material = &look.materials[material];
      const Image* image = group.material->texture.get();
      if (image && !image->empty() && !look.corner_uvs.empty()) {
        if (texture_of[material] == 0) {
          m_textures.push_back(gl::Texture::create());
          texture_of[material] = m_textures.back().get();
          glBindTexture(GL_TEXTURE_2D, texture_of[material]);
          glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, image->width, image->height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                       image->rgba.data());
          glGenerateMipmap(GL_TEXTURE_2D);
          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
          glBindTexture(GL_TEXTURE_2D, 0);
        }
        group.texture = texture_of[material];
      }
      m_groups.push_back(group);
    }
    m_groups.back().count += 3;
    m_split.indices.insert(m_split.indices.end(), split.indices.begin() + 3 * f, split.indices.begin() + 3 * f + 3);
  }
  glBindVertexArray(m_vertex_array.get());
  glBindBuffer(GL_ARRAY_BUFFER, m_colors.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(colors.size() * sizeof(float)), colors.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(2);
  glBindBuffer(GL_ARRAY_BUFFER, m_uvs.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(uvs.size() * sizeof(float)), uvs.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(3);
}

void MeshBuffers::upload(const RenderMesh& mesh) {
  RECOIL_CHECK(mesh.positions.size() % 3 == 0, "positions.size()=" << mesh.positions.size());
  RECOIL_CHECK(mesh.indices.size() % 3 == 0, "indices.size()=" << mesh.indices.size());
  const bool topology_changed = mesh.positions.size() != m_input_floats || mesh.look != m_look ||
                                !std::equal(mesh.indices.begin(), mesh.indices.end(), m_indices.begin(), m_indices.end());
  if (topology_changed) set_topology(mesh);
  else if (mesh.positions == m_sent_positions) return;
  m_input_floats = mesh.positions.size();
  m_sent_positions = mesh.positions;

  const float* positions = mesh.positions.data();
  std::size_t floats = mesh.positions.size();
  if (!m_split.identity) {
    m_split_positions.resize(3 * m_split.source.size());
    for (std::size_t v = 0; v < m_split.source.size(); ++v) {
      const float* p = positions + 3 * std::size_t{m_split.source[v]};
      std::copy(p, p + 3, m_split_positions.begin() + static_cast<std::ptrdiff_t>(3 * v));
    }
    positions = m_split_positions.data();
    floats = m_split_positions.size();
  }
  area_weighted_normals({positions, floats}, m_split.indices, m_normal_data);

  const auto bytes = static_cast<GLsizeiptr>(floats * sizeof(float));
  if (floats > m_capacity) {
    // Grow (never shrink) so a mesh that changes size does not reallocate each frame.
    glBindBuffer(GL_ARRAY_BUFFER, m_positions.get());
    glBufferData(GL_ARRAY_BUFFER, bytes, positions, GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, m_normals.get());
    glBufferData(GL_ARRAY_BUFFER, bytes, m_normal_data.data(), GL_STREAM_DRAW);
    m_capacity = floats;
  } else {
    glBindBuffer(GL_ARRAY_BUFFER, m_positions.get());
    glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, positions);
    glBindBuffer(GL_ARRAY_BUFFER, m_normals.get());
    glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, m_normal_data.data());
  }
}

void MeshBuffers::draw() const {
  if (m_split.indices.empty()) return;
  glBindVertexArray(m_vertex_array.get());
  // Without a look every vertex is white: the program's albedo alone colours it.
  if (!m_look) glVertexAttrib3f(2, 1.0f, 1.0f, 1.0f);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(m_split.indices.size()), GL_UNSIGNED_INT, nullptr);
}

void MeshBuffers::draw(const Group& group) const {
  if (group.count == 0) return;
  glBindVertexArray(m_vertex_array.get());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(group.count), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(group.first * sizeof(std::uint32_t)));
}

}  // namespace recoil::render
