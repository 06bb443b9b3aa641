#pragma once
// Splits a mesh's vertices along sharp edges, so that smooth per-vertex
// normals keep the edges of boxes and the rims of cylinder caps crisp while
// curved surfaces stay smooth. Decided once per topology (from the first
// frame's shape: a deformable box keeps its edges as it bends).
#include <cstdint>
#include <span>
#include <vector>

namespace recoil::render {

struct CreaseSplit {
  std::vector<std::uint32_t> source;   // render vertex -> input vertex
  std::vector<std::uint32_t> indices;  // #F*3, into render vertices
  bool identity = true;                // nothing split: source[i] == i for every input vertex
  // The input is closed and consistently oriented: every edge is shared by
  // exactly two faces that traverse it in opposite directions. Back faces of
  // such a mesh can never be seen from outside and may be culled, which
  // halves llvmpipe's per-triangle work for typical simulation bodies.
  bool closed = false;
};

// Two faces sharing an edge stay smooth across it when their normals differ
// by at most `crease_degrees`; border and non-manifold edges are sharp.
// Corners whose keys differ (`key_stride` floats per corner in `corner_keys`,
// e.g. a colour and texture coordinates) are never joined either, so a UV
// seam splits like a crease. positions: #V*3, indices: #F*3 (all < #V).
// Deterministic: render vertices are numbered in order of their first corner.
CreaseSplit split_creases(std::span<const float> positions, std::span<const std::uint32_t> indices,
                          double crease_degrees, std::span<const float> corner_keys = {}, size_t key_stride = 0);

}  // namespace recoil::render
