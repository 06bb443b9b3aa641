#include "sim/geometry/winding_solid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "core/error.h"
#include "sim/geometry/tetrahedralize.h"
#include "sim/geometry/winding_number.h"

namespace recoil::sim {

WindingSolid winding_solid(const TriMesh& surface, int resolution, int threads) {
  if (resolution < 1) throw bad_input("winding_solid: resolution must be at least 1");
  if (threads < 1) throw bad_input("winding_solid: threads must be at least 1");
  WindingSolid solid;
  if (surface.empty()) return solid;
  const Aabb box = bounding_box(surface);
  const double longest = box.extent().maxCoeff();
  // A surface flat along an axis encloses nothing (and the cells' centres would lie on it).
  if (!(box.extent().minCoeff() > 0.0) || !std::isfinite(longest)) return solid;
  const CubicGrid grid = cubic_grid(box, resolution);
  solid.cell = grid.cell;
  const Eigen::Vector3i& n = grid.cells;
  const WindingNumberTree winding(surface);
  // One z-slab per task: each slab keeps its own cells, so the result is in
  // grid order whatever thread took it.
  std::vector<std::vector<Eigen::Vector3d>> slabs(static_cast<size_t>(n[2]));
  std::atomic<int> next{0};
  auto work = [&] {
    for (int k = next++; k < n[2]; k = next++)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          const Eigen::Vector3d c = grid.center(i, j, k);
          if (inside_by_winding_number(winding(c))) slabs[static_cast<size_t>(k)].push_back(c);
        }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min(threads, n[2]); ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  for (const auto& slab : slabs) solid.centers.insert(solid.centers.end(), slab.begin(), slab.end());
  return solid;
}

}  // namespace recoil::sim
