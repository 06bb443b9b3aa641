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

#include "core/rgba_image.h"

namespace recoil::sim {

struct LookMaterial {
  std::string name;  // as the file names it, control characters replaced
  // The material's own base (diffuse) colour, linear RGB; absent when the
  // file gave none (assimp's default material), so the body's colour shows.
  bool has_color = false;
  std::array<float, 3> color = {1.0f, 1.0f, 1.0f};
  std::shared_ptr<const RgbaImage> texture;  // base-colour map (sRGB), sampled with the corner UVs; null: none
  bool has_uvs = false;         // its triangles carry texture coordinates
  bool vertex_colored = false;  // its triangles carry vertex colours
  // glTF's metallic-roughness factors (assimp also reports a roughness for
  // some FBX materials); absent: the renderer's own highlight.
  bool has_surface = false;
  float metallic = 0.0f;   // 0 dielectric .. 1 metal
  float roughness = 1.0f;  // perceptual roughness, 0 mirror .. 1 matte
};

struct SurfaceLook {
  std::vector<LookMaterial> materials;
  std::vector<std::int32_t> triangle_material;  // #F indices into materials
  std::vector<float> corner_uv;     // #F*6: (u, v) of corners 0, 1, 2 of each triangle; empty: no UVs
  std::vector<float> corner_color;  // #F*9: linear RGB of each corner, in [0, 1]; empty: no vertex colours
  std::vector<std::string> warnings;  // what could not be read (a missing texture), to tell the user

  int num_triangles() const { return static_cast<int>(triangle_material.size()); }
  // Whether it changes anything from a plain body of one colour.
  bool draws_anything() const;
};

// The look of triangles kept[0], kept[1], ... of `look`, in that order.
SurfaceLook select_triangles(const SurfaceLook& look, const std::vector<int>& kept);

// The look after every triangle's corners 1 and 2 were swapped (a mirroring transform).
SurfaceLook with_swapped_corners(const SurfaceLook& look);

// The look as bytes and back (the mesh reader's child hands it to the
// parent), textures left out: they are decoded in children of their own.
void encode_look(const SurfaceLook& look, std::string& bytes);
// Reads what encode_look wrote from `offset` and moves it past; aborts
// (RECOIL_CHECK) on bytes encode_look did not write.
SurfaceLook decode_look(const std::string& bytes, size_t& offset);

// Text from a file made safe to print and to put in JSON: control characters
// and bytes that are not UTF-8 become '?', and at most about `limit` bytes
// are kept ("..." marks a cut).
std::string printable(const std::string& text, size_t limit = 120);

}  // namespace recoil::sim
