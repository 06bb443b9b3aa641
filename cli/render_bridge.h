#pragma once
// Where sim/ meets render/: copies simulation surfaces into the renderer's
// plain RenderScene. Nothing else in cli/ converts.
#include "render/render_scene.h"
#include "sim/geometry/tri_mesh.h"

namespace recoil::cli {

// #V by 3 doubles -> #V*3 floats; triangles copied as they are; the mesh's
// look (materials, textures, vertex colours), if it has one, drawn instead of
// `color` (which still colours the parts the file gave no colour).
render::RenderMesh to_render_mesh(const sim::TriMesh& mesh, const render::Rgb& color, float opacity = 1.0f);

// Replaces the positions of an already converted mesh (same vertex count).
void update_positions(render::RenderMesh& render_mesh, const sim::Points& vertices);

}  // namespace recoil::cli
