#pragma once
// RenderScene: everything the renderer draws, as plain data. cli fills it from
// the simulation's surfaces each frame; render/ knows nothing of physics.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "render/image.h"

namespace recoil::render {

// sRGB-encoded colour components in [0, 1], as users write them ("#d9a066").
using Rgb = std::array<float, 3>;

struct RenderMaterial {
  std::shared_ptr<const Image> texture;  // base-colour map (sRGB); null: none
  // glTF's metallic-roughness factors (surface_shading.h); absent: the studio's highlight.
  bool has_surface = false;
  float metallic = 0.0f;   // 0 dielectric .. 1 metal
  float roughness = 1.0f;  // perceptual, 0 mirror .. 1 matte
};

// How a mesh is drawn when it is more than one colour, per triangle corner.
// Shared and never changed once made, so frames compare it by pointer.
struct RenderLook {
  std::vector<float> corner_colors;  // #F*9 linear RGB; replaces RenderMesh::color
  std::vector<float> corner_uvs;     // #F*6 texture coordinates (v up the image, as OpenGL); empty: no textures
  std::vector<std::uint32_t> triangle_materials;  // #F indices into materials
  std::vector<RenderMaterial> materials;
};

struct RenderMesh {
  std::vector<float> positions;        // #V*3 floats, world space, metres
  std::vector<std::uint32_t> indices;  // #F*3, counter-clockwise seen from outside
  Rgb color = {0.85f, 0.63f, 0.40f};
  float opacity = 1.0f;                // < 1: blended back to front
  std::shared_ptr<const RenderLook> look;  // null: `color` everywhere
  // Moves only as a whole, never changing shape: the depth passes may draw
  // a coarser copy of it made once (depth_proxy.h).
  bool rigid = false;
};

struct RenderScene {
  std::vector<RenderMesh> meshes;
  bool ground = true;            // horizontal plane y = ground_height receiving shadows
  float ground_height = 0.0f;
  bool grid = true;              // soft grid lines on the ground
};

}  // namespace recoil::render
