#pragma once
// MeshBuffers: the GPU copy of one RenderMesh, kept across frames. Positions
// and normals are re-sent every frame (bodies move and deform); indices only
// when they change, which for a simulation is never after the first frame.
#include <cstdint>
#include <vector>

#include "render/gl_objects.h"
#include "render/render_scene.h"

namespace recoil::render {

class MeshBuffers {
 public:
  MeshBuffers();

  // Recomputes normals and uploads. Aborts (RECOIL_CHECK) on malformed
  // arrays: positions not a multiple of 3, an index past the vertex count.
  void upload(const RenderMesh& mesh);

  // Binds the vertex array and draws all triangles (indexed).
  void draw() const;
  std::size_t triangle_count() const { return m_indices.size() / 3; }
  // Closed and consistently oriented (see mesh_topology.h): back faces may be culled.
  bool closed() const { return m_closed; }

 private:
  gl::VertexArray m_vertex_array;
  gl::Buffer m_positions;
  gl::Buffer m_normals;
  gl::Buffer m_elements;
  std::size_t m_vertex_capacity = 0;  // floats the GL buffers hold now
  std::size_t m_vertex_floats = 0;    // floats of the last upload
  std::vector<std::uint32_t> m_indices;  // what m_elements holds
  std::vector<float> m_normal_data;      // scratch, reused every frame
  bool m_closed = false;
};

}  // namespace recoil::render
