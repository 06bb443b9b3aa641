#include "sim/fem/pcg.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <vector>

namespace recoil::sim {

PcgResult solve_pcg(const BlockSparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                    const PcgSettings& settings) {
  const int n = A.block_rows();
  std::vector<Eigen::Matrix3d> inv(static_cast<size_t>(n));
  for (int r = 0; r < n; ++r) {
    const Eigen::Matrix3d& d = A.diagonal_block(r);
    // A singular diagonal block (cannot happen for SPD A) falls back to identity.
    inv[static_cast<size_t>(r)] = std::abs(d.determinant()) > 0.0 ? Eigen::Matrix3d(d.inverse()) : Eigen::Matrix3d(Eigen::Matrix3d::Identity());
  }
  auto precondition = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
    out.resize(in.size());
    for (int r = 0; r < n; ++r) out.segment<3>(3 * r) = inv[static_cast<size_t>(r)] * in.segment<3>(3 * r);
  };

  PcgResult result;
  x = Eigen::VectorXd::Zero(b.size());
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    result.converged = true;
    return result;
  }
  Eigen::VectorXd r = b, z, p, Ap;
  precondition(r, z);
  p = z;
  double rz = r.dot(z);
  for (int it = 0; it < settings.max_iterations; ++it) {
    A.multiply(p, Ap);
    const double pAp = p.dot(Ap);
    if (!(pAp > 0.0)) break;  // not SPD along p (or NaN): report non-convergence
    const double alpha = rz / pAp;
    x.noalias() += alpha * p;
    r.noalias() -= alpha * Ap;
    result.iterations = it + 1;
    result.relative_residual = r.norm() / b_norm;
    if (result.relative_residual <= settings.relative_tolerance) {
      result.converged = true;
      return result;
    }
    precondition(r, z);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return result;
}

}  // namespace recoil::sim
