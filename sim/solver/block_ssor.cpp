#include "sim/solver/block_ssor.h"

#include <Eigen/SparseCore>

#include "core/check.h"

namespace recoil::sim {

constexpr double kOmega = 1.5;

BlockSsor::BlockSsor(const BlockSparseMatrix& A, const std::vector<Eigen::Matrix3d>& inv_diag) : m_inv_diag(inv_diag) {
  const int n = A.block_rows();
  RECOIL_CHECK(static_cast<int>(inv_diag.size()) == n);
  // A is symmetric in pattern and values: block column c of the scalar
  // matrix lists the block rows r with (r, c) stored, so row r of the
  // pattern is column r (first scalar column of the block, zeros kept).
  const Eigen::SparseMatrix<double> scalar = A.to_eigen();
  m_lower_start.assign(static_cast<size_t>(n) + 1, 0);
  m_upper_start.assign(static_cast<size_t>(n) + 1, 0);
  for (int r = 0; r < n; ++r) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(scalar, 3 * r); it; ++it) {
      if (it.row() % 3 != 0) continue;
      const int c = static_cast<int>(it.row()) / 3;
      if (c == r) continue;
      const int index = A.find(r, c);
      RECOIL_CHECK(index >= 0, "block (" << r << ", " << c << ") missing from a symmetric pattern");
      (c < r ? m_lower : m_upper).emplace_back(c, &A.block(index));
    }
    m_lower_start[static_cast<size_t>(r) + 1] = static_cast<int>(m_lower.size());
    m_upper_start[static_cast<size_t>(r) + 1] = static_cast<int>(m_upper.size());
  }
}

void BlockSsor::apply(const Eigen::VectorXd& x, Eigen::VectorXd& out) const {
  const int n = static_cast<int>(m_inv_diag.size());
  out.resize(3 * n);
  // Forward: (D + L) u = x, u kept in out.
  for (int r = 0; r < n; ++r) {
    Eigen::Vector3d s = x.segment<3>(3 * r);
    for (int k = m_lower_start[static_cast<size_t>(r)]; k < m_lower_start[static_cast<size_t>(r) + 1]; ++k) {
      const auto& [c, block] = m_lower[static_cast<size_t>(k)];
      s.noalias() -= *block * out.segment<3>(3 * c);
    }
    out.segment<3>(3 * r) = kOmega * (m_inv_diag[static_cast<size_t>(r)] * s);
  }
  // Backward: (D + L^T) z = D u, i.e. z_r = u_r - D_r^-1 sum_{c > r} A_rc z_c.
  for (int r = n - 1; r >= 0; --r) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (int k = m_upper_start[static_cast<size_t>(r)]; k < m_upper_start[static_cast<size_t>(r) + 1]; ++k) {
      const auto& [c, block] = m_upper[static_cast<size_t>(k)];
      s.noalias() += *block * out.segment<3>(3 * c);
    }
    out.segment<3>(3 * r) = kOmega * (out.segment<3>(3 * r) - m_inv_diag[static_cast<size_t>(r)] * s);
  }
  out *= (2.0 - kOmega) / kOmega;
}

}  // namespace recoil::sim
