// Co-rotated linear elasticity (McAdams et al. 2011 energy). With the signed
// SVD F = U diag(s) V^T (reflection folded into s_2), R = U V^T, S = R^T F:
//   P = 2 mu (F - R) + lambda (tr S - 3) R,       d tr S / dF = R,
//   dR/dF = sum_{i<j} q_ij q_ij^T / (s_i + s_j),  q_ij = vec(u_i v_j^T - u_j v_i^T),
// (from R^T dR skew and dF = dR S + R dS), hence
//   dP/dF = 2 mu I + lambda r r^T + (lambda (tr S - 3) - 2 mu) dR/dF,  r = vec(R).
// The q_ij are orthogonal (|q|^2 = 2) and orthogonal to r, so the eigenvalues
// are 2 mu (x5), 2 mu + 3 lambda (along r) and, along each q_ij,
// 2 mu + 2 (lambda (tr S - 3) - 2 mu) / (s_i + s_j): only these can be negative.
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

DensityEval corotated_density(const Eigen::Matrix3d& F, const Lame& lame, HessianMode mode) {
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
  if (mode == HessianMode::none) return out;

  const Vector9d r = Eigen::Map<const Vector9d>(R.data());
  out.dPdF = 2.0 * lame.mu * Matrix9d::Identity() + lame.lambda * r * r.transpose();
  const double twist_coefficient = lame.lambda * tr_s_minus_3 - 2.0 * lame.mu;
  const double scale = std::max(1.0, s.cwiseAbs().maxCoeff());
  constexpr int kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (const auto& [i, j] : kPairs) {
    double denom = s[i] + s[j];
    if (std::abs(denom) < kMinSigmaSum * scale) denom = denom < 0.0 ? -kMinSigmaSum * scale : kMinSigmaSum * scale;
    double c = twist_coefficient / denom;
    // Eigenvalue along q_ij is 2 mu + 2 c; clamp it at zero when projecting.
    if (mode == HessianMode::projected && 2.0 * lame.mu + 2.0 * c < 0.0) c = -lame.mu;
    const Eigen::Matrix3d q = U.col(i) * V.col(j).transpose() - U.col(j) * V.col(i).transpose();
    const Vector9d qv = Eigen::Map<const Vector9d>(q.data());
    out.dPdF.noalias() += c * qv * qv.transpose();
  }
  return out;
}

}  // namespace recoil::sim
