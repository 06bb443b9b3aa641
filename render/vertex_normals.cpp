#include "render/vertex_normals.h"

#include <algorithm>
#include <cmath>

namespace recoil::render {

void area_weighted_normals(std::span<const float> positions, std::span<const std::uint32_t> indices,
                           std::vector<float>& normals) {
  normals.assign(positions.size(), 0.0f);
  const float* p = positions.data();
  float* n = normals.data();
  const size_t index_count = indices.size() - indices.size() % 3;
  for (size_t f = 0; f < index_count; f += 3) {
    const size_t a = 3 * size_t{indices[f]}, b = 3 * size_t{indices[f + 1]}, c = 3 * size_t{indices[f + 2]};
    const float e1x = p[b] - p[a], e1y = p[b + 1] - p[a + 1], e1z = p[b + 2] - p[a + 2];
    const float e2x = p[c] - p[a], e2y = p[c + 1] - p[a + 1], e2z = p[c + 2] - p[a + 2];
    // The unnormalised cross product is twice the area times the unit normal.
    const float nx = e1y * e2z - e1z * e2y;
    const float ny = e1z * e2x - e1x * e2z;
    const float nz = e1x * e2y - e1y * e2x;
    for (size_t v : {a, b, c}) {
      n[v] += nx;
      n[v + 1] += ny;
      n[v + 2] += nz;
    }
  }
  for (size_t v = 0; v < normals.size(); v += 3) {
    const float length = std::sqrt(n[v] * n[v] + n[v + 1] * n[v + 1] + n[v + 2] * n[v + 2]);
    if (length > 1e-30f && std::isfinite(length)) {
      const float inverse = 1.0f / length;
      n[v] *= inverse;
      n[v + 1] *= inverse;
      n[v + 2] *= inverse;
    } else {
      n[v] = 0.0f;
      n[v + 1] = 1.0f;
      n[v + 2] = 0.0f;
    }
  }
}

}  // namespace recoil::render
