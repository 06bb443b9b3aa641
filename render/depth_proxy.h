#pragma once
// A coarser copy of a mesh's surface for the passes that draw depth alone
// (the key light's shadow map, the occlusion's depth), through
// meshoptimizer's edge collapses: a million-triangle scan costs those passes
// as much as the lit pass itself, while the map's texels are far coarser than
// its triangles.
#include <cstdint>
#include <span>
#include <vector>

namespace recoil::render {

// Triangles (#F'*3, into the same vertices, same winding) of a surface that
// stays within `relative_error` times the mesh's largest extent of the input;
// the input's own indices when no collapse keeps it that close.
// positions: #V*3 floats; indices: #F*3, all < #V. Deterministic.
std::vector<std::uint32_t> depth_proxy_indices(std::span<const float> positions, std::span<const std::uint32_t> indices,
                                               float relative_error);

}  // namespace recoil::render
