#pragma once
// BlockSparseMatrix: a square sparse matrix of 3x3 blocks (one block row per
// node), stored in block-CSR with sorted columns, both triangles present. The
// pattern is fixed at construction; values are accumulated in place, so
// assembly order (and hence rounding) is the caller's deterministic order.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

namespace recoil::sim {

class BlockSparseMatrix {
 public:
  BlockSparseMatrix() = default;
  // pairs: (row, col) block coordinates, duplicates allowed; the diagonal is
  // always included.
  BlockSparseMatrix(int block_rows, std::vector<std::pair<int, int>> pairs);

  int block_rows() const { return m_rows; }
  int rows() const { return 3 * m_rows; }
  int num_blocks() const { return static_cast<int>(m_cols.size()); }

  // Index of block (r, c) in the storage, or -1 if it is not in the pattern.
  int find(int r, int c) const;
  Eigen::Matrix3d& block(int index) { return m_blocks[static_cast<size_t>(index)]; }
  const Eigen::Matrix3d& block(int index) const { return m_blocks[static_cast<size_t>(index)]; }
  const Eigen::Matrix3d& diagonal_block(int r) const { return m_blocks[static_cast<size_t>(m_diag[static_cast<size_t>(r)])]; }

  void set_zero();
  // Makes block row and column r an identity row/column (a fixed node).
  void fix(const std::vector<char>& fixed);

  // y = A x; x and y have 3 * block_rows() entries.
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // y = |A| |x| entry by entry: the scale of the rounding error of A x.
  void multiply_magnitudes(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;

  Eigen::SparseMatrix<double> to_eigen() const;

 private:
  int m_rows = 0;
  std::vector<int> m_row_start;   // block_rows + 1
  std::vector<int> m_cols;        // per stored block
  std::vector<int> m_diag;        // storage index of (r, r)
  std::vector<Eigen::Matrix3d> m_blocks;
};

}  // namespace recoil::sim
