#include "render/depth_proxy.h"

#include <meshoptimizer.h>

namespace recoil::render {

std::vector<std::uint32_t> depth_proxy_indices(std::span<const float> positions, std::span<const std::uint32_t> indices,
                                               float relative_error) {
  if (indices.empty()) return {};
  std::vector<std::uint32_t> kept(indices.size());
  // A target of no triangles at all: the error bound alone stops the collapses.
  const size_t count = meshopt_simplify(kept.data(), indices.data(), indices.size(), positions.data(),
                                        positions.size() / 3, 3 * sizeof(float), 0, relative_error, 0, nullptr);
  kept.resize(count);
  return kept;
}

}  // namespace recoil::render
