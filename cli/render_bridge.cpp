#include "cli/render_bridge.h"

#include "core/check.h"

namespace recoil::cli {

void update_positions(render::RenderMesh& render_mesh, const sim::Points& vertices) {
  render_mesh.positions.resize(static_cast<size_t>(vertices.rows()) * 3);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    for (int k = 0; k < 3; ++k) render_mesh.positions[3 * v + k] = static_cast<float>(vertices(v, k));
}

render::RenderMesh to_render_mesh(const sim::TriMesh& mesh, const render::Rgb& color, float opacity) {
  render::RenderMesh out;
  update_positions(out, mesh.vertices);
  out.indices.resize(static_cast<size_t>(mesh.num_triangles()) * 3);
  for (int f = 0; f < mesh.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) {
      RECOIL_CHECK(mesh.triangles(f, k) >= 0 && mesh.triangles(f, k) < mesh.num_vertices());
      out.indices[3 * f + k] = static_cast<std::uint32_t>(mesh.triangles(f, k));
    }
  out.color = color;
  out.opacity = opacity;
  return out;
}

}  // namespace recoil::cli
