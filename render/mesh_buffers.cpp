#include "render/mesh_buffers.h"

#include <algorithm>

#include "core/check.h"
#include "render/vertex_normals.h"

namespace recoil::render {

MeshBuffers::MeshBuffers()
    : m_vertex_array(gl::VertexArray::create()),
      m_positions(gl::Buffer::create()),
      m_normals(gl::Buffer::create()),
      m_elements(gl::Buffer::create()) {
  glBindVertexArray(m_vertex_array.get());
  glBindBuffer(GL_ARRAY_BUFFER, m_positions.get());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, m_normals.get());
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_elements.get());
  glBindVertexArray(0);
}

void MeshBuffers::set_topology(const RenderMesh& mesh) {
  const auto vertex_count = static_cast<std::uint32_t>(mesh.positions.size() / 3);
  const auto worst = std::max_element(mesh.indices.begin(), mesh.indices.end());
  RECOIL_CHECK(worst == mesh.indices.end() || *worst < vertex_count,
               "index " << *worst << " >= vertex count " << vertex_count);
  m_indices = mesh.indices;
  m_split = split_creases(mesh.positions, mesh.indices, kCreaseDegrees);
  glBindVertexArray(m_vertex_array.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m_split.indices.size() * sizeof(std::uint32_t)),
               m_split.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

void MeshBuffers::upload(const RenderMesh& mesh) {
  RECOIL_CHECK(mesh.positions.size() % 3 == 0, "positions.size()=" << mesh.positions.size());
  RECOIL_CHECK(mesh.indices.size() % 3 == 0, "indices.size()=" << mesh.indices.size());
  const bool topology_changed = mesh.positions.size() != m_input_floats ||
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
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(m_split.indices.size()), GL_UNSIGNED_INT, nullptr);
}

}  // namespace recoil::render
