#include "sim/geometry/mesh_simplify.h"

#include <meshoptimizer.h>

#include <vector>

#include "core/check.h"

namespace recoil::sim {

SimplifiedMesh simplify_mesh(const TriMesh& mesh, int target_triangles) {
  RECOIL_CHECK(target_triangles > 0);
  // Float positions relative to the box centre keep the input's precision.
  const Aabb box = bounding_box(mesh);
  const Eigen::Vector3d centre = box.center();
  std::vector<float> positions(static_cast<size_t>(mesh.num_vertices()) * 3);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k) positions[static_cast<size_t>(3 * v + k)] = static_cast<float>(mesh.vertices(v, k) - centre[k]);
  std::vector<unsigned int> indices(static_cast<size_t>(mesh.num_triangles()) * 3);
  for (int f = 0; f < mesh.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) indices[static_cast<size_t>(3 * f + k)] = static_cast<unsigned int>(mesh.triangles(f, k));

  std::vector<unsigned int> kept(indices.size());
  float error = 0.0f;
  // An error bound of 1 (the whole extent) lets the triangle count decide.
  size_t count = meshopt_simplify(kept.data(), indices.data(), indices.size(), positions.data(), positions.size() / 3,
                                        3 * sizeof(float), 3 * static_cast<size_t>(target_triangles), 1.0f, 0, &error);
  // Borders (an open mesh's holes, a CAD part's many shells) stop the edge
  // collapses early; vertex clustering then reaches the target regardless of
  // topology, which a collision surface can afford.
  if (count > 6 * static_cast<size_t>(target_triangles))
    count = meshopt_simplifySloppy(kept.data(), indices.data(), indices.size(), positions.data(), positions.size() / 3,
                                   3 * sizeof(float), 3 * static_cast<size_t>(target_triangles), 1.0f, &error);
  kept.resize(count);

  SimplifiedMesh out;
  out.relative_error = error;
  std::vector<int> remap(static_cast<size_t>(mesh.num_vertices()), -1);
  int used = 0;
  for (unsigned int v : kept)
    if (remap[v] < 0) remap[v] = used++;
  out.mesh.vertices.resize(used, 3);
  out.source.resize(used);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (remap[static_cast<size_t>(v)] >= 0) {
      out.mesh.vertices.row(remap[static_cast<size_t>(v)]) = mesh.vertices.row(v);
      out.source[remap[static_cast<size_t>(v)]] = v;
    }
  out.mesh.triangles.resize(static_cast<Eigen::Index>(count / 3), 3);
  for (size_t i = 0; i < count; ++i)
    out.mesh.triangles(static_cast<Eigen::Index>(i / 3), static_cast<Eigen::Index>(i % 3)) = remap[kept[i]];
  return out;
}

}  // namespace recoil::sim
