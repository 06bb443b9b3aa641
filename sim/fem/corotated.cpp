// Co-rotated linear elasticity (McAdams et al. 2011 energy). Derivatives:
//   P = 2 mu (F - R) + lambda (tr S - 3) R,     S = R^T F, d tr S / dF = R,
//   dP = 2 mu (dF - dR) + lambda (R : dF) R + lambda (tr S - 3) dR,
//   dR = U W V^T with W skew, W_ij = (M_ij - M_ji) / (s_i + s_j), M = U^T dF V.
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>

#include "sim/fem/material.h"

namespace recoil::sim {

namespace {
// Sums of singular values below this (relative to their scale) make dR blow up
// (a fully flattened element); they are clamped, and the Hessian is projected.
constexpr double kMinSigmaSum = 1e-8;
}  // namespace

DensityEval corotated_density(const Eigen::Matrix3d& F, const Lame& lame, bool want_hessian) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU(), V = svd.matrixV();
  Eigen::Vector3d s = svd.singularValues();
  // Fold reflections into the smallest singular value so R is a rotation.
  if (U.determinant() < 0.0) { U.col(2) = -U.col(2); s[2] = -s[2]; }
  if (V.determinant() < 0.0) { V.col(2) = -V.col(2); s[2] = -s[2]; }
  const Eigen::Matrix3d R = U * V.transpose();
  const double tr_s_minus_3 = s.sum() - 3.0;

  DensityEval out;
  out.psi = lame.mu * (F - R).squaredNorm() + 0.5 * lame.lambda * tr_s_minus_3 * tr_s_minus_3;
  out.P = 2.0 * lame.mu * (F - R) + lame.lambda * tr_s_minus_3 * R;
  if (!want_hessian) return out;

  const double scale = std::max(1.0, s.cwiseAbs().maxCoeff());
  for (int col = 0; col < 9; ++col) {
    Eigen::Matrix3d dF = Eigen::Matrix3d::Zero();
    dF(col % 3, col / 3) = 1.0;
    const Eigen::Matrix3d M = U.transpose() * dF * V;
    Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) {
        double denom = s[i] + s[j];
        if (std::abs(denom) < kMinSigmaSum * scale) denom = denom < 0.0 ? -kMinSigmaSum * scale : kMinSigmaSum * scale;
        W(i, j) = (M(i, j) - M(j, i)) / denom;
        W(j, i) = -W(i, j);
      }
    const Eigen::Matrix3d dR = U * W * V.transpose();
    const Eigen::Matrix3d dP = 2.0 * lame.mu * (dF - dR) + lame.lambda * R(col % 3, col / 3) * R +
                               lame.lambda * tr_s_minus_3 * dR;
    out.dPdF.col(col) = Eigen::Map<const Vector9d>(dP.data());
  }
  out.dPdF = 0.5 * (out.dPdF + out.dPdF.transpose()).eval();
  return out;
}

}  // namespace recoil::sim
