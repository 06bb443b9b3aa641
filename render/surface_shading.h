#pragma once
// How a material's glTF metallic-roughness factors map onto the studio
// shading (Lambert plus a Blinn-Phong highlight of the key light):
// - roughness r gives the highlight's exponent through the Beckmann slope
//   alpha = r^2, e = 2 / alpha^2 - 2 (the exponent whose lobe has alpha's
//   width), clamped to [1, 4096], and its peak the normalised Blinn-Phong
//   factor (e + 8) relative to the studio's own e = 48, so a narrower lobe
//   is brighter and a matte one nearly vanishes;
// - metallic m scales the diffuse colour by (1 - m), tints the highlight
//   from the studio's white 0.25 towards the base colour, and reflects the
//   sky and ground ambient in the base colour along the mirror direction,
//   so a metal without an environment map is not black between highlights.
// A material without the factors keeps the studio's highlight exactly.
#include "render/render_scene.h"

namespace recoil::render {

struct SurfaceShading {
  static constexpr float kStudioExponent = 48.0f;  // the studio's own highlight

  float metallic = 0.0f;    // 0 dielectric .. 1 metal
  float shininess = kStudioExponent;  // Blinn-Phong exponent of the key's highlight
  float highlight = 1.0f;   // the highlight's peak relative to the studio's
};

SurfaceShading surface_shading(const RenderMaterial& material);

}  // namespace recoil::render
