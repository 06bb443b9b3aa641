#pragma once
// Smooth per-vertex normals of a triangle mesh, recomputed every frame
// because deformable bodies change shape.
#include <cstdint>
#include <span>
#include <vector>

namespace recoil::render {

// normals (#V*3, resized) = the normalised sum of the incident faces' normals
// weighted by face area. positions: #V*3 floats; indices: #F*3, all < #V.
// A vertex with no incident area gets +y (it only matters for lighting).
// Faces are visited in order, so the result is deterministic.
void area_weighted_normals(std::span<const float> positions, std::span<const std::uint32_t> indices,
                           std::vector<float>& normals);

}  // namespace recoil::render
