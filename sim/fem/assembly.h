#pragma once
// Assembly of the implicit-Euler system for the deformable bodies, one
// linearisation per step, with stiffness-proportional damping D = beta K:
//   A = M + (h beta + h^2) K,
//   b = h (f_el(x) + M g) - h (beta + h) K v,
// with K the (projected) elastic Hessian, so that A dv = b, v += dv, x += h v.
// K annihilates translations, and rotations of an unstressed body, so the
// damping force -beta K v acts on deformation only (docs/decisions/001-damping-acts-on-deformation-only.md).
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "sim/fem/block_sparse.h"
#include "sim/fem/deformable_body.h"

namespace recoil::sim {

// Global block coordinates (node pairs) the body's tets couple.
std::vector<std::pair<int, int>> block_pairs(const DeformableBody& body);

// Fills body.block_index from the pattern of A (which must contain block_pairs).
void index_blocks(DeformableBody& body, const BlockSparseMatrix& A);

// Gathers the 12 coordinates of tet t from a global vector (3 per node).
Vector12d gather(const DeformableBody& body, int t, const Eigen::VectorXd& global);

// Adds the body's rows to A and b (A, b zeroed by the caller). x, v: global,
// 3 per node. Pinned rows get b = 0; call A.fix() after all bodies.
// Returns the body's elastic energy at x, J.
double assemble_body(const DeformableBody& body, const Eigen::VectorXd& x, const Eigen::VectorXd& v, double h,
                     const Eigen::Vector3d& gravity, BlockSparseMatrix& A, Eigen::VectorXd& b);

struct ElasticState {
  double energy = 0.0;             // J (0 unless asked for)
  double min_volume_ratio = 1.0;   // min over tets of current / rest volume
  int inverted = 0;                // tets with volume ratio <= 0
};
// Volume ratios from det F (cheap); the energy needs an SVD per element for
// the co-rotated model, so it is only computed when asked for.
ElasticState elastic_state(const DeformableBody& body, const Eigen::VectorXd& x, bool with_energy);

}  // namespace recoil::sim
