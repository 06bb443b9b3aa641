#pragma once
// RenderScene: everything the renderer draws, as plain data. cli fills it from
// the simulation's surfaces each frame; render/ knows nothing of physics.
#include <array>
#include <cstdint>
#include <vector>

namespace recoil::render {

// sRGB-encoded colour components in [0, 1], as users write them ("#d9a066").
using Rgb = std::array<float, 3>;

struct RenderMesh {
  std::vector<float> positions;        // #V*3 floats, world space, metres
  std::vector<std::uint32_t> indices;  // #F*3, counter-clockwise seen from outside
  Rgb color = {0.85f, 0.63f, 0.40f};
  float opacity = 1.0f;                // < 1: blended back to front
};

struct RenderScene {
  std::vector<RenderMesh> meshes;
  bool ground = true;            // horizontal plane y = ground_height receiving shadows
  float ground_height = 0.0f;
  bool grid = true;              // soft grid lines on the ground
};

}  // namespace recoil::render
