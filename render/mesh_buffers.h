#pragma once
// MeshBuffers: the GPU copy of one RenderMesh, kept across frames. Positions
// and normals are re-sent whenever the positions changed (bodies move and
// deform; a static body or a turntable's mesh is sent once); the index buffer
// only when the topology changes, which for a simulation is never after the
// first frame. Vertices on sharp edges are split (crease_split.h) so smooth
// normals keep boxes boxy. A mesh with a look (render_scene.h) is split
// further where corners differ in colour or texture coordinates, each side
// keeping the normal of its smooth group (a UV seam is no lighting seam), and
// its triangles are drawn grouped by material. A rigid mesh's depth passes
// draw a coarser copy of its triangles over the same vertices (depth_proxy.h).
#include <cstdint>
#include <memory>
#include <vector>

#include "render/crease_split.h"
#include "render/gl_objects.h"
#include "render/render_scene.h"
#include "render/shadow_map.h"
#include "render/surface_shading.h"

namespace recoil::render {

class MeshBuffers {
 public:
  // Faces meeting at more than this keep a hard edge between them.
  static constexpr double kCreaseDegrees = 40.0;
  // meshoptimizer's error target for a rigid mesh's depth copy, as a share
  // of the mesh's largest extent: a quarter of a texel of the largest shadow
  // map, which spans the scene's bounding sphere and so at least the mesh. The
  // estimate is a mean over the merged faces, not a largest distance; the
  // largest measured on a torus is about a texel (depth_proxy_test), inside
  // the 1.5 texels by which receivers look the map up off their own surface.
  static constexpr float kDepthProxyError = 0.25f / static_cast<float>(ShadowMap::kLargestSize);

  MeshBuffers();

  // Recomputes normals and uploads, unless the mesh is the one uploaded last; true when it uploaded. Aborts
  // (RECOIL_CHECK) on malformed arrays: positions not a multiple of 3, an index past the vertex count, a look of
  // another triangle count.
  bool upload(const RenderMesh& mesh);

  // Binds the vertex array and draws all triangles (indexed).
  void draw() const;
  // Triangles that share a material, drawn together: elements [first, first + count) of the drawn indices.
  struct Group {
    std::size_t first = 0, count = 0;
    std::shared_ptr<const Image> texture;  // null: none
    SurfaceShading shading;
  };
  // Empty without a look: then draw() in one colour.
  const std::vector<Group>& groups() const { return m_groups; }
  void draw(const Group& group) const;
  // Positions only, for a depth pass: the coarser copy where there is one, else all triangles.
  void draw_depth() const;
  std::size_t triangle_count() const { return m_indices.size() / 3; }
  std::size_t depth_triangle_count() const;
  bool has_depth_copy() const { return m_depth_indices > 0; }
  // Closed and consistently oriented (see crease_split.h): back faces may be culled.
  bool closed() const { return m_smooth.closed; }

 private:
  void set_topology(const RenderMesh& mesh);
  // The look's vertices (m_drawn), their colours and UVs, and the material groups.
  void set_look(const RenderMesh& mesh);
  // The coarser copy's triangles over the drawn vertices, for a rigid mesh.
  void set_depth_proxy(const RenderMesh& mesh);

  gl::VertexArray m_vertex_array;
  gl::Buffer m_positions;
  gl::Buffer m_normals;
  gl::Buffer m_elements;
  gl::Buffer m_colors;  // per drawn vertex: linear RGB (a look only)
  gl::Buffer m_uvs;     // per drawn vertex: texture coordinates (a look only)
  gl::VertexArray m_depth_array;  // positions and the coarser copy's triangles
  gl::Buffer m_depth_elements;
  std::size_t m_depth_indices = 0;  // in m_depth_elements; 0: no coarser copy
  std::size_t m_capacity = 0;            // floats each vertex buffer holds now
  std::size_t m_input_floats = 0;        // mesh.positions.size() of the last upload
  std::vector<std::uint32_t> m_indices;  // the mesh's own indices, to spot changes
  std::vector<float> m_sent_positions;   // the mesh's positions as last uploaded, to spot changes
  std::shared_ptr<const RenderLook> m_look;  // the look of the last topology
  bool m_rigid = false;                      // ... and whether it was rigid
  CreaseSplit m_smooth;  // smooth groups: the vertices normals are averaged over
  // Without a look, the drawn vertices are m_smooth's. With one: drawn vertex
  // -> input vertex (source) and -> smooth vertex (m_smooth_of), and the
  // indices drawn, grouped by material.
  CreaseSplit m_drawn;
  std::vector<std::uint32_t> m_smooth_of;
  std::vector<Group> m_groups;
  std::vector<float> m_gathered;     // scratch: positions per smooth vertex
  std::vector<float> m_normal_data;  // scratch: normals per smooth vertex
  std::vector<float> m_drawn_positions, m_drawn_normals;  // scratch: per drawn vertex (a look only)
};

}  // namespace recoil::render
