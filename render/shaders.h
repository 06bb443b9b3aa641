#pragma once
// GLSL 3.30 sources of the renderer's programs. Lighting happens in linear
// space; the sRGB framebuffer encodes on write. Fragment outputs are
// premultiplied by alpha (blend ONE, ONE_MINUS_SRC_ALPHA) so that a
// transparent background can be un-premultiplied exactly at the end.
#include <string>

namespace recoil::render::shaders {

// Meshes: position (location 0), normal (1), linear colour multiplying the
// albedo (2) and texture coordinates (3), studio lighting; `shadows` compiles
// the key light's shadow-map lookups in, `textured` a base-colour map's,
// `occlusion` the ambient occlusion's (ambient_occlusion.h).
std::string mesh_vertex();
std::string mesh_fragment(bool shadows, bool textured, bool occlusion);
// The ground plane: lit like a matte mesh plus the grid and the distance fade.
std::string ground_vertex();
std::string ground_fragment(bool shadows, bool grid, bool occlusion);
// The ground as a shadow catcher (over a transparent background): the key
// light's shadow alone, as black coverage; no floor colour, no grid.
std::string shadow_catcher_fragment();
// Depth only, from the key light (shadow map) — position attribute only.
std::string depth_vertex();
std::string depth_fragment();
// Ambient occlusion: a full-screen triangle (no attributes), the occlusion
// from a depth texture, and the 4x4 box blur that follows it.
std::string fullscreen_vertex();
std::string occlusion_fragment();
std::string box_blur_fragment();
// The meshes' layer laid over the frame (render_target.h): the mean of a
// pixel's `samples` (0: a single-sample texture), premultiplied.
std::string lay_over_fragment(int samples);
// Flat colour, for the wireframe overlay.
std::string flat_fragment();

}  // namespace recoil::render::shaders
