// Stable Neo-Hookean (Smith, de Goes, Kim 2018, section 3 energy without the
// log barrier). With J = det F and its cofactor dJ/dF = [f1 x f2, f2 x f0, f0 x f1]
// (columns f_k of F):
//   P  = mu F + lambda' (J - a) dJ/dF,
//   dP = mu dF + lambda' (dJ/dF : dF) dJ/dF + lambda' (J - a) d(dJ/dF)[dF].
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "sim/fem/material.h"
#include "sim/geometry/skew.h"

namespace recoil::sim {

namespace {
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& F) {
  Eigen::Matrix3d c;
  c.col(0) = F.col(1).cross(F.col(2));
  c.col(1) = F.col(2).cross(F.col(0));
  c.col(2) = F.col(0).cross(F.col(1));
  return c;
}
}  // namespace

DensityEval neo_hookean_density(const Eigen::Matrix3d& F, const Lame& lame, HessianMode mode) {
  const double mu = lame.mu;
  const double lambda = lame.lambda + lame.mu;
  const double alpha = 1.0 + mu / lambda;
  const double J = F.determinant();
  const Eigen::Matrix3d dJ = cofactor(F);

  DensityEval out;
  // The constant shifts psi(I) to zero: lambda'/2 (1 - a)^2 = mu^2 / (2 lambda').
  out.psi = 0.5 * mu * (F.squaredNorm() - 3.0) + 0.5 * lambda * ((J - alpha) * (J - alpha) - (1.0 - alpha) * (1.0 - alpha));
  out.P = mu * F + lambda * (J - alpha) * dJ;
  if (mode == HessianMode::none) return out;

  const Vector9d g = Eigen::Map<const Vector9d>(dJ.data());
  out.dPdF = mu * Matrix9d::Identity() + lambda * g * g.transpose();
  // d(cofactor)[dF] is linear in dF; its 9x9 matrix has 3x3 blocks (a, b)
  // equal to the cross-product matrices of the third column, with signs.
  Matrix9d H = Matrix9d::Zero();
  // d(f1 x f2) = df1 x f2 + f1 x df2 = -[f2]x df1 + [f1]x df2, and cyclic.
  const Eigen::Vector3d f0 = F.col(0), f1 = F.col(1), f2 = F.col(2);
  H.block<3, 3>(0, 3) = -skew(f2);
  H.block<3, 3>(0, 6) = skew(f1);
  H.block<3, 3>(3, 0) = skew(f2);
  H.block<3, 3>(3, 6) = -skew(f0);
  H.block<3, 3>(6, 0) = -skew(f1);
  H.block<3, 3>(6, 3) = skew(f0);
  out.dPdF += lambda * (J - alpha) * H;
  if (mode == HessianMode::projected) project_psd(out.dPdF);
  return out;
}

}  // namespace recoil::sim
