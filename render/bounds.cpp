#include "render/bounds.h"

#include <algorithm>

namespace recoil::render {

Bounds bounds_of(const std::vector<float>& positions) {
  float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                 std::numeric_limits<float>::infinity()};
  float hi[3] = {-lo[0], -lo[1], -lo[2]};
  for (size_t i = 0; i + 2 < positions.size(); i += 3) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], positions[i + static_cast<size_t>(k)]);
      hi[k] = std::max(hi[k], positions[i + static_cast<size_t>(k)]);
    }
  }
  Bounds b;
  if (positions.size() >= 3) {
    b.lo = Eigen::Vector3d(lo[0], lo[1], lo[2]);
    b.hi = Eigen::Vector3d(hi[0], hi[1], hi[2]);
  }
  return b;
}

}  // namespace recoil::render
