#pragma once
// Block SSOR as a preconditioner for A (3x3 blocks):
//   M = omega / (2 - omega) (D / omega + L) D^-1 (D / omega + L^T),
// D the diagonal blocks, L the strict lower block triangle, omega = 1.5
// (against omega = 1, symmetric Gauss-Seidel: -14% to +10% iterations on
// the FEM bench, and one E = 1e7 solve that froze into an unconverged state
// with omega = 1 converged). M is SPD whenever A is and 0 < omega < 2, so it may stand for P_A
// in the CR preconditioner C = diag(P_A, P_S). One application of M^-1 (a
// forward and a backward block sweep) costs about one product with A.
// A^-1 is never formed.
#include <Eigen/Core>
#include <vector>

#include "sim/fem/block_sparse.h"

namespace recoil::sim {

class BlockSsor {
 public:
  // Reads the block pattern of A once (through A.to_eigen(), O(#blocks));
  // keeps pointers to A's blocks, so A must outlive this and keep its values.
  BlockSsor(const BlockSparseMatrix& A, const std::vector<Eigen::Matrix3d>& inv_diag);

  // out = M^-1 x; x and out have A.rows() entries (out may not alias x).
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& out) const;

 private:
  const std::vector<Eigen::Matrix3d>& m_inv_diag;
  std::vector<int> m_lower_start, m_upper_start;  // per block row, into m_lower / m_upper
  std::vector<std::pair<int, const Eigen::Matrix3d*>> m_lower, m_upper;  // (column, block)
};

}  // namespace recoil::sim
