#include "render/mesh_buffers.h"

#include <algorithm>
#include <numeric>

#include "core/check.h"
#include "render/depth_proxy.h"
#include "render/vertex_normals.h"

namespace recoil::render {
namespace {

// values[source[v]] for every v, `width` floats each.
void gather(const float* values, const std::vector<std::uint32_t>& source, size_t width, std::vector<float>& out) {
  out.resize(width * source.size());
  for (size_t v = 0; v < source.size(); ++v) std::copy_n(values + width * source[v], width, out.data() + width * v);
}

// Creates or refills `buffer` with `data` (grows, never shrinks, so a mesh
// that changes size does not reallocate each frame).
void send(GLuint buffer, const std::vector<float>& data, bool grow) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  const auto bytes = static_cast<GLsizeiptr>(data.size() * sizeof(float));
  if (grow) glBufferData(GL_ARRAY_BUFFER, bytes, data.data(), GL_STREAM_DRAW);
  else glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, data.data());
}

}  // namespace

MeshBuffers::MeshBuffers()
    : m_vertex_array(gl::VertexArray::create()),
      m_positions(gl::Buffer::create()),
      m_normals(gl::Buffer::create()),
      m_elements(gl::Buffer::create()),
      m_colors(gl::Buffer::create()),
      m_uvs(gl::Buffer::create()),
      m_depth_array(gl::VertexArray::create()),
      m_depth_elements(gl::Buffer::create()) {
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
  glBindVertexArray(m_depth_array.get());
  glBindBuffer(GL_ARRAY_BUFFER, m_positions.get());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_depth_elements.get());
  glBindVertexArray(0);
}

void MeshBuffers::set_topology(const RenderMesh& mesh) {
  const auto vertex_count = static_cast<std::uint32_t>(mesh.positions.size() / 3);
  const auto worst = std::max_element(mesh.indices.begin(), mesh.indices.end());
  RECOIL_CHECK(worst == mesh.indices.end() || *worst < vertex_count,
               "index " << *worst << " >= vertex count " << vertex_count);
  m_indices = mesh.indices;
  m_look = mesh.look;
  m_smooth = split_creases(mesh.positions, mesh.indices, kCreaseDegrees);
  m_groups.clear();
  m_capacity = 0;  // the drawn vertex count may have changed
  glBindVertexArray(m_vertex_array.get());
  if (mesh.look) {
    set_look(mesh);
  } else {
    glDisableVertexAttribArray(2);
    glDisableVertexAttribArray(3);
  }
  const std::vector<std::uint32_t>& drawn = mesh.look ? m_drawn.indices : m_smooth.indices;
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(drawn.size() * sizeof(std::uint32_t)), drawn.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
  m_rigid = mesh.rigid;
  set_depth_proxy(mesh);
}

void MeshBuffers::set_depth_proxy(const RenderMesh& mesh) {
  m_depth_indices = 0;
  if (!mesh.rigid || mesh.indices.empty()) return;
  // Simplified over the input's own vertices, where no crease or seam splits
  // the surface, then moved onto one drawn copy of each (same position).
  std::vector<std::uint32_t> proxy = depth_proxy_indices(mesh.positions, mesh.indices, kDepthProxyError);
  if (proxy.size() >= mesh.indices.size()) return;
  const std::vector<std::uint32_t>& source = m_look ? m_drawn.source : m_smooth.source;
  if (m_look || !m_smooth.identity) {
    std::vector<std::uint32_t> drawn_of(mesh.positions.size() / 3, 0);
    for (size_t v = source.size(); v-- > 0;) drawn_of[source[v]] = static_cast<std::uint32_t>(v);
    for (std::uint32_t& i : proxy) i = drawn_of[i];
  }
  glBindVertexArray(m_depth_array.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(proxy.size() * sizeof(std::uint32_t)), proxy.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
  m_depth_indices = proxy.size();
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
  // Keyed corners are joined only where they are also smooth, so each drawn
  // vertex lies in one smooth group.
  const CreaseSplit keyed = split_creases(mesh.positions, mesh.indices, kCreaseDegrees, keys, kStride);
  const size_t drawn_vertices = keyed.source.size();
  std::vector<float> colors(3 * drawn_vertices, 1.0f), uvs(2 * drawn_vertices, 0.0f);
  m_smooth_of.assign(drawn_vertices, 0);
  for (size_t c = 0; c < keyed.indices.size(); ++c) {
    const size_t v = keyed.indices[c];
    std::copy_n(keys.data() + kStride * c, 3, colors.data() + 3 * v);
    std::copy_n(keys.data() + kStride * c + 3, 2, uvs.data() + 2 * v);
    m_smooth_of[v] = m_smooth.indices[c];
  }
  // Triangles grouped by material, in their own order within a group.
  std::vector<std::uint32_t> order(faces);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return look.triangle_materials[a] < look.triangle_materials[b];
  });
  m_drawn.source = keyed.source;
  m_drawn.indices.clear();
  m_drawn.indices.reserve(keyed.indices.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const std::uint32_t f = order[i];
    const std::uint32_t material = look.triangle_materials[f];
    if (i == 0 || material != look.triangle_materials[order[i - 1]]) {
      Group group;
      group.first = m_drawn.indices.size();
      if (!look.corner_uvs.empty()) group.texture = look.materials[material].texture;
      group.shading = surface_shading(look.materials[material]);
      m_groups.push_back(group);
    }
    m_groups.back().count += 3;
    m_drawn.indices.insert(m_drawn.indices.end(), keyed.indices.begin() + 3 * f, keyed.indices.begin() + 3 * f + 3);
  }
  glBindBuffer(GL_ARRAY_BUFFER, m_colors.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(colors.size() * sizeof(float)), colors.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(2);
  glBindBuffer(GL_ARRAY_BUFFER, m_uvs.get());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(uvs.size() * sizeof(float)), uvs.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(3);
}

bool MeshBuffers::upload(const RenderMesh& mesh) {
  RECOIL_CHECK(mesh.positions.size() % 3 == 0, "positions.size()=" << mesh.positions.size());
  RECOIL_CHECK(mesh.indices.size() % 3 == 0, "indices.size()=" << mesh.indices.size());
  const bool topology_changed = mesh.positions.size() != m_input_floats || mesh.look != m_look || mesh.rigid != m_rigid ||
                                !std::equal(mesh.indices.begin(), mesh.indices.end(), m_indices.begin(), m_indices.end());
  if (topology_changed) set_topology(mesh);
  else if (mesh.positions == m_sent_positions) return false;
  m_input_floats = mesh.positions.size();
  m_sent_positions = mesh.positions;

  // Normals over the smooth groups; a look's drawn vertices take their group's.
  const std::vector<float>* positions = &mesh.positions;
  if (!m_smooth.identity) {
    gather(mesh.positions.data(), m_smooth.source, 3, m_gathered);
    positions = &m_gathered;
  }
  area_weighted_normals(*positions, m_smooth.indices, m_normal_data);
  const std::vector<float>* normals = &m_normal_data;
  if (m_look) {
    gather(mesh.positions.data(), m_drawn.source, 3, m_drawn_positions);
    gather(m_normal_data.data(), m_smooth_of, 3, m_drawn_normals);
    positions = &m_drawn_positions;
    normals = &m_drawn_normals;
  }
  const bool grow = positions->size() > m_capacity;
  send(m_positions.get(), *positions, grow);
  send(m_normals.get(), *normals, grow);
  if (grow) m_capacity = positions->size();
  return true;
}

void MeshBuffers::draw() const {
  const std::vector<std::uint32_t>& drawn = m_look ? m_drawn.indices : m_smooth.indices;
  if (drawn.empty()) return;
  glBindVertexArray(m_vertex_array.get());
  // Without a look every vertex is white: the program's albedo alone colours it.
  if (!m_look) glVertexAttrib3f(2, 1.0f, 1.0f, 1.0f);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(drawn.size()), GL_UNSIGNED_INT, nullptr);
}

void MeshBuffers::draw_depth() const {
  if (m_depth_indices == 0) {
    draw();
    return;
  }
  glBindVertexArray(m_depth_array.get());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(m_depth_indices), GL_UNSIGNED_INT, nullptr);
}

std::size_t MeshBuffers::depth_triangle_count() const {
  return m_depth_indices > 0 ? m_depth_indices / 3 : triangle_count();
}

void MeshBuffers::draw(const Group& group) const {
  if (group.count == 0) return;
  glBindVertexArray(m_vertex_array.get());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(group.count), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(group.first * sizeof(std::uint32_t)));
}

}  // namespace recoil::render
