#include "sim/geometry/tet_mesh.h"

#include <algorithm>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <utility>

#include "core/check.h"

namespace recoil::sim {

double tet_volume(const Points& nodes, const Tets& tets, int t) {
  const Eigen::Vector3d x0 = nodes.row(tets(t, 0)).transpose();
  const Eigen::Vector3d e1 = nodes.row(tets(t, 1)).transpose() - x0;
  const Eigen::Vector3d e2 = nodes.row(tets(t, 2)).transpose() - x0;
  const Eigen::Vector3d e3 = nodes.row(tets(t, 3)).transpose() - x0;
  return e1.dot(e2.cross(e3)) / 6.0;
}

double total_volume(const TetMesh& mesh) {
  double v = 0.0;
  for (int t = 0; t < mesh.num_tets(); ++t) v += tet_volume(mesh, t);
  return v;
}

double longest_tet_edge(const TetMesh& mesh) {
  double longest = 0.0;
  for (int t = 0; t < mesh.num_tets(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        longest = std::max(longest, (mesh.nodes.row(mesh.tets(t, a)) - mesh.nodes.row(mesh.tets(t, b))).norm());
  return longest;
}

int orient_positive(TetMesh& mesh, int* degenerate, double eps_rel) {
  const Aabb box = bounding_box(mesh.nodes);
  const double diag = box.valid() ? box.extent().norm() : 0.0;
  const double eps = eps_rel * diag * diag * diag;
  int flipped = 0, flat = 0;
  for (int t = 0; t < mesh.num_tets(); ++t) {
    const double v = tet_volume(mesh, t);
    if (std::abs(v) <= eps) {
      ++flat;
    } else if (v < 0.0) {
      std::swap(mesh.tets(t, 2), mesh.tets(t, 3));
      ++flipped;
    }
  }
  if (degenerate) *degenerate = flat;
  return flipped;
}

Eigen::VectorXi remove_unused_nodes(TetMesh& mesh) {
  Eigen::VectorXi map = Eigen::VectorXi::Constant(mesh.num_nodes(), -1);
  for (int t = 0; t < mesh.num_tets(); ++t)
    for (int k = 0; k < 4; ++k) {
      const int n = mesh.tets(t, k);
      RECOIL_CHECK(n >= 0 && n < mesh.num_nodes(), "tet " << t << " node " << n);
      map[n] = 0;
    }
  int next = 0;
  for (int i = 0; i < map.size(); ++i)
    if (map[i] == 0) map[i] = next++;
  Points kept(next, 3);
  for (int i = 0; i < map.size(); ++i)
    if (map[i] >= 0) kept.row(map[i]) = mesh.nodes.row(i);
  for (int t = 0; t < mesh.num_tets(); ++t)
    for (int k = 0; k < 4; ++k) mesh.tets(t, k) = map[mesh.tets(t, k)];
  mesh.nodes = std::move(kept);
  return map;
}

void transform_in_place(TetMesh& mesh, const Eigen::Matrix3d& rotation,
                        const Eigen::Vector3d& scale, const Eigen::Vector3d& translation) {
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Eigen::Vector3d p = mesh.nodes.row(i).transpose();
    mesh.nodes.row(i) = (rotation * scale.cwiseProduct(p) + translation).transpose();
  }
  if (scale.prod() * rotation.determinant() < 0.0) mesh.tets.col(2).swap(mesh.tets.col(3));
}

}  // namespace recoil::sim
