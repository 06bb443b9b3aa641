#pragma once
// TetMesh: a linear tetrahedral mesh, the volume discretisation of a
// deformable body.
#include <Eigen/Core>

#include "sim/geometry/tri_mesh.h"

namespace recoil::sim {

// Row-major so one row is one tet's four node indices.
using Tets = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;

struct TetMesh {
  Points nodes;  // #N by 3, metres
  Tets tets;     // #T by 4, positively oriented: det[x1-x0, x2-x0, x3-x0] > 0

  int num_nodes() const { return static_cast<int>(nodes.rows()); }
  int num_tets() const { return static_cast<int>(tets.rows()); }
  bool empty() const { return tets.rows() == 0; }
};

// Signed volume of tet t (positive for the orientation above), m^3.
double tet_volume(const Points& nodes, const Tets& tets, int t);
inline double tet_volume(const TetMesh& mesh, int t) { return tet_volume(mesh.nodes, mesh.tets, t); }

// Sum of signed tet volumes, m^3.
double total_volume(const TetMesh& mesh);

// The longest edge of any tet, m (0 without tets).
double longest_tet_edge(const TetMesh& mesh);

// Swaps two indices of every negatively oriented tet. Returns how many were
// flipped. Degenerate tets (|volume| <= eps_rel * bbox_diag^3) are left alone
// and counted in `degenerate` when given.
int orient_positive(TetMesh& mesh, int* degenerate = nullptr, double eps_rel = 1e-14);

// Drops nodes no tet uses and renumbers the tets (node order is preserved).
// Returns, for each old node, its new index or -1.
Eigen::VectorXi remove_unused_nodes(TetMesh& mesh);

// Applies p -> R * (s .* p) + t to every node, then restores positive
// orientation if the scale mirrors.
void transform_in_place(TetMesh& mesh, const Eigen::Matrix3d& rotation,
                        const Eigen::Vector3d& scale, const Eigen::Vector3d& translation);

}  // namespace recoil::sim
