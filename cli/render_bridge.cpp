#include "cli/render_bridge.h"

#include "core/check.h"
#include "render/srgb.h"

namespace recoil::cli {

void update_positions(render::RenderMesh& render_mesh, const sim::Points& vertices) {
  render_mesh.positions.resize(static_cast<size_t>(vertices.rows()) * 3);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    for (int k = 0; k < 3; ++k) render_mesh.positions[3 * v + k] = static_cast<float>(vertices(v, k));
}

std::shared_ptr<const render::RenderLook> to_render_look(const sim::SurfaceLook& look, const render::Rgb& body_color) {
  auto out = std::make_shared<render::RenderLook>();
  const std::array<float, 3> plain = render::srgb_to_linear(body_color);
  std::vector<std::array<float, 3>> base;
  for (const sim::LookMaterial& m : look.materials) {
    render::RenderMaterial material;
    if (m.has_uvs && !look.corner_uv.empty()) material.texture = m.texture;  // the image itself: no copy
    material.has_surface = m.has_surface;
    material.metallic = m.metallic;
    material.roughness = m.roughness;
    out->materials.push_back(material);
    const bool tinted = material.texture || m.vertex_colored;
    base.push_back(m.has_color ? m.color : tinted ? std::array<float, 3>{1.0f, 1.0f, 1.0f} : plain);
  }
  const size_t faces = look.triangle_material.size();
  const bool vertex_colors = !look.corner_color.empty();
  out->triangle_materials.assign(look.triangle_material.begin(), look.triangle_material.end());
  out->corner_colors.resize(9 * faces);
  for (size_t c = 0; c < 3 * faces; ++c)
    for (size_t k = 0; k < 3; ++k)
      out->corner_colors[3 * c + k] = base[static_cast<size_t>(look.triangle_material[c / 3])][k] *
                                      (vertex_colors ? look.corner_color[3 * c + k] : 1.0f);
  out->corner_uvs = look.corner_uv;
  return out;
}

std::shared_ptr<const render::RenderLook> RenderLookCache::get(const std::shared_ptr<const sim::SurfaceLook>& look,
                                                               const render::Rgb& body_color) {
  auto& cached = m_looks[{look, body_color}];
  if (!cached) cached = to_render_look(*look, body_color);
  return cached;
}

render::RenderMesh to_render_mesh(const sim::TriMesh& mesh, const render::Rgb& color, float opacity,
                                  RenderLookCache* looks) {
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
  if (mesh.look && mesh.look->draws_anything()) {
    RECOIL_CHECK(mesh.look->num_triangles() == mesh.num_triangles(),
                 "look of " << mesh.look->num_triangles() << " triangles for " << mesh.num_triangles());
    out.look = looks ? looks->get(mesh.look, color) : to_render_look(*mesh.look, color);
  }
  return out;
}

}  // namespace recoil::cli
