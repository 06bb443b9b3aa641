#pragma once
// Embedding of a (fine) surface in a (coarse) tet mesh: each surface vertex is
// bound to one tet by barycentric weights, so the surface follows the
// deformation: p = sum_k w_k x_{tet_k}. Vertices just outside the mesh bind to
// the nearest tet with extrapolating (some negative) weights; the weights
// still sum to 1 and reproduce the vertex exactly at rest.
#include <Eigen/Core>

#include "sim/geometry/tet_mesh.h"

namespace recoil::sim {

using Weights4 = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;

struct Embedding {
  Eigen::VectorXi tet;  // #V: the tet each vertex is bound to
  Weights4 weights;     // #V by 4: barycentric weights over that tet's nodes
  int outside = 0;      // vertices bound to a nearest (not containing) tet
};

// points: #V by 3. The mesh must be non-empty with positive tets.
Embedding embed_points(const TetMesh& mesh, const Points& points);

// Barycentric coordinates of p in tet t of (nodes, tets): 4 weights summing to 1.
Eigen::Vector4d barycentric(const Points& nodes, const Tets& tets, int t, const Eigen::Vector3d& p);

// Positions of the embedded vertices for node positions `nodes` (#N by 3).
// Output #V by 3.
void embedded_positions(const Embedding& embedding, const Tets& tets, const Points& nodes, Points& out);

}  // namespace recoil::sim
