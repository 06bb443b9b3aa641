#pragma once
// Where sim/ meets render/: copies simulation surfaces into the renderer's
// plain RenderScene. Nothing else in cli/ converts.
#include <map>
#include <memory>
#include <utility>

#include "render/render_scene.h"
#include "sim/geometry/tri_mesh.h"

namespace recoil::cli {

// The look as the renderer takes it: each corner's colour is its material's
// base colour times its vertex colour, linear. A material without a colour
// of its own is white under a texture or vertex colours, else the body's
// colour (`body_color`, sRGB). Textures are shared, not copied.
std::shared_ptr<const render::RenderLook> to_render_look(const sim::SurfaceLook& look, const render::Rgb& body_color);

// Converted looks by look and body colour, so that many bodies of one mesh
// (a pile of copies) share one.
class RenderLookCache {
 public:
  std::shared_ptr<const render::RenderLook> get(const std::shared_ptr<const sim::SurfaceLook>& look,
                                                const render::Rgb& body_color);

 private:
  std::map<std::pair<std::shared_ptr<const sim::SurfaceLook>, render::Rgb>, std::shared_ptr<const render::RenderLook>>
      m_looks;
};

// #V by 3 doubles -> #V*3 floats; triangles copied as they are; the mesh's
// look (materials, textures, vertex colours), if it has one, drawn instead of
// `color` (which still colours the parts the file gave no colour), through
// `looks` when given.
render::RenderMesh to_render_mesh(const sim::TriMesh& mesh, const render::Rgb& color, float opacity = 1.0f,
                                  RenderLookCache* looks = nullptr);

// Replaces the positions of an already converted mesh (same vertex count).
void update_positions(render::RenderMesh& render_mesh, const sim::Points& vertices);

}  // namespace recoil::cli
