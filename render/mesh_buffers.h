#pragma once
// MeshBuffers: the GPU copy of one RenderMesh, kept across frames. Positions
// and normals are re-sent whenever the positions changed (bodies move and
// deform; a static body or a turntable's mesh is sent once); the index buffer
// only when the topology changes, which for a simulation is never after the
// first frame. Vertices on sharp edges are split (crease_split.h)
// so smooth normals keep boxes boxy, and so are vertices whose corners differ
// in colour or texture coordinates (a mesh's look, render_scene.h). The
// triangles of a look are drawn grouped by material, one draw per group.
#include <cstdint>
#include <memory>
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
  // Triangles that share a material, drawn together: elements
  // [first, first + count) of the drawn indices.
  struct Group {
    std::size_t first = 0, count = 0;
    const RenderMaterial* material = nullptr;
    GLuint texture = 0;  // 0: none
  };
  // Empty without a look: then draw() in one colour.
  const std::vector<Group>& groups() const { return m_groups; }
  void draw(const Group& group) const;
  std::size_t triangle_count() const { return m_indices.size() / 3; }
  // Closed and consistently oriented (see crease_split.h): back faces may be culled.
  bool closed() const { return m_split.closed; }

 private:
  void set_topology(const RenderMesh& mesh);
  // The look's per-corner keys, the render vertices' colours and UVs, and the material groups.
  void set_look(const RenderMesh& mesh);

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
  gl::Buffer m_colors;                   // per render vertex: linear RGB (a look only)
  gl::Buffer m_uvs;                      // per render vertex: texture coordinates (a look only)
  std::shared_ptr<const RenderLook> m_look;  // the look of the last topology
  std::vector<gl::Texture> m_textures;   // one per material with a texture
  std::vector<Group> m_groups;
};

}  // namespace recoil::render
