#include "render/mesh_topology.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace recoil::render {

bool is_closed_oriented(std::span<const std::uint32_t> indices) {
  if (indices.empty() || indices.size() % 3 != 0) return false;
  // Each directed edge a->b as ((min, max), a > b). In a closed, oriented
  // mesh every undirected edge occurs exactly twice, once each way, so after
  // sorting the entries come in pairs (e, 0), (e, 1) and no edge repeats.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;
  edges.reserve(indices.size());
  for (size_t f = 0; f < indices.size(); f += 3) {
    for (size_t k = 0; k < 3; ++k) {
      const std::uint64_t a = indices[f + k], b = indices[f + (k + 1) % 3];
      if (a == b) return false;  // degenerate triangle
      edges.emplace_back((std::min(a, b) << 32) | std::max(a, b), a > b ? 1u : 0u);
    }
  }
  if (edges.size() % 2 != 0) return false;
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size(); i += 2) {
    if (edges[i].first != edges[i + 1].first || edges[i].second != 0 || edges[i + 1].second != 1) return false;
    if (i + 2 < edges.size() && edges[i + 2].first == edges[i].first) return false;
  }
  return true;
}

}  // namespace recoil::render
