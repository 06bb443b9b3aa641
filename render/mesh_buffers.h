#pragma once
// MeshBuffers: the GPU copy of one RenderMesh, kept across frames. Positions
// and normals are re-sent whenever the positions changed (bodies move and
// deform; a static body or a turntable's mesh is sent once); the index buffer
// only when the topology changes, which for a simulation is never after the
// first frame. Vertices on sharp edges are split (crease_split.h)
// so smooth normals keep boxes boxy.
#include <cstdint>
#include <vector>

#include "render/crease_split.h"
#include "render/gl_objects.h"
#include "render/render_scene.h"

namespace recoil::render {

class MeshBuffers {
 public:
  // Faces meeting at more than this keep a hard edge between them.
  static constexpr double kCreaseDegrees = 40.0;

  MeshBuffers();

  // Recomputes normals and uploads, unless the mesh is the one uploaded last. Aborts (RECOIL_CHECK) on malformed
  // arrays: positions not a multiple of 3, an index past the vertex count.
  void upload(const RenderMesh& mesh);

  // Binds the vertex array and draws all triangles (indexed).
  void draw() const;
  std::size_t triangle_count() const { return m_indices.size() / 3; }
  // Closed and consistently oriented (see crease_split.h): back faces may be culled.
  bool closed() const { return m_split.closed; }

 private:
  void set_topology(const RenderMesh& mesh);

  gl::VertexArray m_vertex_array;
  gl::Buffer m_positions;
  gl::Buffer m_normals;
  gl::Buffer m_elements;
  std::size_t m_capacity = 0;          // floats each vertex buffer holds now
  std::size_t m_input_floats = 0;      // mesh.positions.size() of the last upload
  std::vector<std::uint32_t> m_indices;  // the mesh's own indices, to spot changes
  std::vector<float> m_sent_positions;   // the mesh's positions as last uploaded, to spot changes
  CreaseSplit m_split;                   // render vertices and the indices drawn
  std::vector<float> m_split_positions;  // scratch: positions gathered per render vertex
  std::vector<float> m_normal_data;      // scratch, reused every frame
};

}  // namespace recoil::render
