#include "sim/fem/block_sparse.h"

#include <algorithm>

#include "core/check.h"

namespace recoil::sim {

BlockSparseMatrix::BlockSparseMatrix(int block_rows, std::vector<std::pair<int, int>> pairs) : m_rows(block_rows) {
  for (int r = 0; r < block_rows; ++r) pairs.emplace_back(r, r);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  m_row_start.assign(static_cast<size_t>(block_rows) + 1, 0);
  m_cols.reserve(pairs.size());
  m_diag.assign(static_cast<size_t>(block_rows), -1);
  for (const auto& [r, c] : pairs) {
    RECOIL_CHECK(r >= 0 && r < block_rows && c >= 0 && c < block_rows, "block " << r << "," << c);
    if (r == c) m_diag[static_cast<size_t>(r)] = static_cast<int>(m_cols.size());
    m_cols.push_back(c);
    ++m_row_start[static_cast<size_t>(r) + 1];
  }
  for (int r = 0; r < block_rows; ++r) m_row_start[static_cast<size_t>(r) + 1] += m_row_start[static_cast<size_t>(r)];
  m_blocks.assign(m_cols.size(), Eigen::Matrix3d::Zero());
}

int BlockSparseMatrix::find(int r, int c) const {
  const auto begin = m_cols.begin() + m_row_start[static_cast<size_t>(r)];
  const auto end = m_cols.begin() + m_row_start[static_cast<size_t>(r) + 1];
  const auto it = std::lower_bound(begin, end, c);
  return (it != end && *it == c) ? static_cast<int>(it - m_cols.begin()) : -1;
}

void BlockSparseMatrix::set_zero() {
  for (auto& b : m_blocks) b.setZero();
}

void BlockSparseMatrix::fix(const std::vector<char>& fixed) {
  RECOIL_CHECK(static_cast<int>(fixed.size()) == m_rows);
  for (int r = 0; r < m_rows; ++r)
    for (int k = m_row_start[static_cast<size_t>(r)]; k < m_row_start[static_cast<size_t>(r) + 1]; ++k) {
      const int c = m_cols[static_cast<size_t>(k)];
      if (fixed[static_cast<size_t>(r)] || fixed[static_cast<size_t>(c)])
        m_blocks[static_cast<size_t>(k)] = r == c ? Eigen::Matrix3d(Eigen::Matrix3d::Identity()) : Eigen::Matrix3d(Eigen::Matrix3d::Zero());
    }
}

void BlockSparseMatrix::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  RECOIL_CHECK(x.size() == rows());
  y.resize(rows());
  for (int r = 0; r < m_rows; ++r) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int k = m_row_start[static_cast<size_t>(r)]; k < m_row_start[static_cast<size_t>(r) + 1]; ++k)
      sum.noalias() += m_blocks[static_cast<size_t>(k)] * x.segment<3>(3 * m_cols[static_cast<size_t>(k)]);
    y.segment<3>(3 * r) = sum;
  }
}

void BlockSparseMatrix::multiply_magnitudes(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  RECOIL_CHECK(x.size() == rows());
  y.resize(rows());
  for (int r = 0; r < m_rows; ++r) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int k = m_row_start[static_cast<size_t>(r)]; k < m_row_start[static_cast<size_t>(r) + 1]; ++k)
      sum.noalias() += m_blocks[static_cast<size_t>(k)].cwiseAbs() * x.segment<3>(3 * m_cols[static_cast<size_t>(k)]).cwiseAbs();
    y.segment<3>(3 * r) = sum;
  }
}

Eigen::SparseMatrix<double> BlockSparseMatrix::to_eigen() const {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(m_blocks.size() * 9);
  for (int r = 0; r < m_rows; ++r)
    for (int k = m_row_start[static_cast<size_t>(r)]; k < m_row_start[static_cast<size_t>(r) + 1]; ++k)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          triplets.emplace_back(3 * r + i, 3 * m_cols[static_cast<size_t>(k)] + j, m_blocks[static_cast<size_t>(k)](i, j));
  Eigen::SparseMatrix<double> out(rows(), rows());
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

}  // namespace recoil::sim
