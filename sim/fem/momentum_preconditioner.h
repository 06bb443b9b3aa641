#pragma once
// P_A^-1: the approximate inverse of a step's matrix A = M + h D + h^2 K that
// the step's solvers precondition with and measure momentum errors by (m/s).
// It is the inverted 3x3 diagonal blocks D of A plus, for each deformable
// body, the inverse of A on the body's six rigid motions Z (the coarse term
// alone maps A Z c back to Z c; D^-1 adds its own part on top):
//   P_A^-1 = D^-1 + sum_b Z_b (Z_b^T A Z_b)^-1 Z_b^T,   Z_b: #DoF by 6.
// A stiff body's diagonal blocks hold h^2 k >> m, so D^-1 alone reads a net
// force on it as a velocity error h^2 k / m times too small, and moves its
// rigid motion that many times too slowly (docs/decisions/005-rigid-mode-correction.md).
#include <Eigen/Core>
#include <vector>

#include "sim/fem/block_sparse.h"

namespace recoil::sim {

// The free DoF nodes of one deformable body and where they are (m). Its rigid
// motions move node i by t + w x (x_i - c), with c the nodes' centroid.
struct RigidModeNodes {
  std::vector<int> nodes;                  // DoF nodes of the body, fixed nodes left out
  std::vector<Eigen::Vector3d> positions;  // one per node
};

class MomentumPreconditioner {
 public:
  using ModeBlock = Eigen::Matrix<double, 3, 6>;  // Z restricted to one node: [I, -[arm]x]
  using CoarseMatrix = Eigen::Matrix<double, 6, 6>;
  using CoarseVector = Eigen::Matrix<double, 6, 1>;
  using Vector = Eigen::Ref<const Eigen::VectorXd>;

  // Block Jacobi alone when `bodies` is empty. A has no blocks coupling two
  // bodies (contacts are rows, not entries of A).
  explicit MomentumPreconditioner(const BlockSparseMatrix& A, const std::vector<RigidModeNodes>& bodies = {});

  // out = P_A^-1 x; both #DoF (out sized by the caller, not aliasing x).
  void apply(const Vector& x, Eigen::Ref<Eigen::VectorXd> out) const;
  // |P_A^-1 x|^2, or a partial sum above stop_above once it passes it (the
  // sum only grows): a stop test that is passed early need not read every node.
  double applied_squared_norm(const Vector& x, double stop_above) const;

  // D^-1 for one node, and all of them.
  const Eigen::Matrix3d& diagonal_inverse(int node) const { return m_inv_diag[static_cast<size_t>(node)]; }
  const std::vector<Eigen::Matrix3d>& diagonal_inverses() const { return m_inv_diag; }

  // The rigid-mode term, for kernels that apply P_A^-1 through a few rows:
  // the body a node's rigid modes belong to (-1: none), that node's block of
  // Z, and (Z_b^T A Z_b)^-1 in 1/kg (the rotations' arms are divided by the
  // body's RMS arm, so Z is dimensionless).
  int body_of(int node) const { return m_body_of_node.empty() ? -1 : m_body_of_node[static_cast<size_t>(node)]; }
  ModeBlock mode_block(int node) const;
  const CoarseMatrix& coarse_inverse(int body) const { return m_coarse_inverse[static_cast<size_t>(body)]; }

 private:
  // Per body, the rigid motion S_b^-1 Z_b^T x of the coarse term.
  std::vector<CoarseVector> coarse_solution(const Vector& x) const;
  // Rigid motion c (translation, rotation) of a body at one of its nodes: Z_i c.
  Eigen::Vector3d motion_at(const CoarseVector& c, int node) const {
    return c.head<3>() + c.tail<3>().cross(m_arm[static_cast<size_t>(node)]);
  }

  std::vector<Eigen::Matrix3d> m_inv_diag;     // per node
  std::vector<int> m_body_of_node;             // per node, or empty without bodies
  std::vector<std::vector<int>> m_body_nodes;  // per body, its nodes
  std::vector<Eigen::Vector3d> m_arm;          // per node: (x_i - c) / RMS arm of its body (0 outside bodies)
  std::vector<CoarseMatrix> m_coarse_inverse;  // per body
};

}  // namespace recoil::sim
