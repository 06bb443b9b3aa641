#pragma once
// SurfaceLook: how an imported surface is drawn (materials, textures, vertex
// colours). Only the renderer reads it; the simulation never does. It is kept
// per triangle corner, so it survives welding (a UV seam's two sides share a
// position but keep their own coordinates) and any motion of the vertices.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace recoil::sim {

// 8-bit RGBA, sRGB-encoded colour, rows top first (as image files store them).
struct LookImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes
};

struct LookMaterial {
  std::string name;
  // The material's own base (diffuse) colour, linear RGB; absent when the
  // file gave none (assimp's default material), so the body's colour shows.
  bool has_color = false;
  std::array<float, 3> color = {1.0f, 1.0f, 1.0f};
  std::shared_ptr<const LookImage> texture;  // base-colour map, sampled with the corner UVs; null: none
};

struct SurfaceLook {
  std::vector<LookMaterial> materials;
  std::vector<std::int32_t> triangle_material;  // #F indices into materials
  std::vector<float> corner_uv;     // #F*6: (u, v) of corners 0, 1, 2 of each triangle; empty: no UVs
  std::vector<float> corner_color;  // #F*9: linear RGB of each corner; empty: no vertex colours
  std::vector<std::string> warnings;  // what could not be read (a missing texture), to tell the user

  int num_triangles() const { return static_cast<int>(triangle_material.size()); }
  // Whether it changes anything from a plain body of one colour.
  bool draws_anything() const;
};

// The look of triangles kept[0], kept[1], ... of `look`, in that order.
SurfaceLook select_triangles(const SurfaceLook& look, const std::vector<int>& kept);

// The look after every triangle's corners 1 and 2 were swapped (a mirroring transform).
SurfaceLook with_swapped_corners(const SurfaceLook& look);

}  // namespace recoil::sim

namespace recoil::sim {

// The look as bytes and back (the mesh reader's child hands it to the parent).
// decode_look reads from `offset`, moves it past what it read, and aborts
// (RECOIL_CHECK) on bytes encode_look did not write.
void encode_look(const SurfaceLook& look, std::string& bytes);
SurfaceLook decode_look(const std::string& bytes, size_t& offset);

}  // namespace recoil::sim
