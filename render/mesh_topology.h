#pragma once
// Whether a triangle mesh is closed and consistently oriented. The renderer
// culls back faces of such meshes (their inside can't be seen from outside),
// which halves llvmpipe's per-triangle work for typical simulation bodies;
// open or inconsistent meshes are drawn two-sided.
#include <cstdint>
#include <span>

namespace recoil::render {

// True when every edge is shared by exactly two triangles that traverse it in
// opposite directions. indices: #F*3. An empty mesh is not closed.
bool is_closed_oriented(std::span<const std::uint32_t> indices);

}  // namespace recoil::render
