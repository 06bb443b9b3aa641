#include "render/surface_shading.h"

#include <algorithm>

namespace recoil::render {

SurfaceShading surface_shading(const RenderMaterial& material) {
  SurfaceShading out;
  if (!material.has_surface) return out;
  const float alpha = std::max(material.roughness * material.roughness, 1e-3f);
  out.shininess = std::clamp(2.0f / (alpha * alpha) - 2.0f, 1.0f, 4096.0f);
  out.highlight = (out.shininess + 8.0f) / (SurfaceShading::kStudioExponent + 8.0f);
  out.metallic = std::clamp(material.metallic, 0.0f, 1.0f);
  return out;
}

}  // namespace recoil::render
