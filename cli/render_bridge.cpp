#include "cli/render_bridge.h"

#include <map>

#include "core/check.h"
#include "render/srgb.h"

namespace recoil::cli {

void update_positions(render::RenderMesh& render_mesh, const sim::Points& vertices) {
  render_mesh.positions.resize(static_cast<size_t>(vertices.rows()) * 3);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    for (int k = 0; k < 3; ++k) render_mesh.positions[3 * v + k] = static_cast<float>(vertices(v, k));
}

namespace {

// The look as the renderer takes it: each corner's colour is its material's
// base colour times its vertex colour, linear. A material without a colour
// of its own is white under a texture or vertex colours, else the body's colour.
std::shared_ptr<const render::RenderLook> to_render_look(const sim::SurfaceLook& look, const render::Rgb& body_color) {
  auto out = std::make_shared<render::RenderLook>();
  const std::array<float, 3> plain = render::srgb_to_linear(body_color);
  const bool vertex_colors = !look.corner_color.empty();
  std::map<const sim::LookImage*, std::shared_ptr<const render::Image>> converted;
  std::vector<std::array<float, 3>> base;
  for (const sim::LookMaterial& m : look.materials) {
    render::RenderMaterial material;
    if (m.texture) {
      auto& image = converted[m.texture.get()];
      if (!image) {
        auto copy = std::make_shared<render::Image>();
        copy->width = m.texture->width;
        copy->height = m.texture->height;
        copy->rgba = m.texture->rgba;
        image = std::move(copy);
      }
      material.texture = image;
    }
    out->materials.push_back(material);
    const bool tinted = material.texture || vertex_colors;
    base.push_back(m.has_color ? m.color : tinted ? std::array<float, 3>{1.0f, 1.0f, 1.0f} : plain);
  }
  const size_t faces = look.triangle_material.size();
  out->triangle_materials.assign(look.triangle_material.begin(), look.triangle_material.end());
  out->corner_colors.resize(9 * faces);
  for (size_t c = 0; c < 3 * faces; ++c)
    for (size_t k = 0; k < 3; ++k)
      out->corner_colors[3 * c + k] = base[static_cast<size_t>(look.triangle_material[c / 3])][k] *
                                      (vertex_colors ? look.corner_color[3 * c + k] : 1.0f);
  out->corner_uvs = look.corner_uv;
  return out;
}

}  // namespace

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
  if (mesh.look && mesh.look->draws_anything()) {
    RECOIL_CHECK(mesh.look->num_triangles() == mesh.num_triangles(),
                 "look of " << mesh.look->num_triangles() << " triangles for " << mesh.num_triangles());
    out.look = to_render_look(*mesh.look, color);
  }
  return out;
}

}  // namespace recoil::cli
