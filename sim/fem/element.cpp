#include "sim/fem/element.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/LU>

#include "core/check.h"

namespace recoil::sim {

namespace {
// dF/dx: vec(F)_(i+3j) depends on node a's coordinate i through g_a[j], with
// g_a = row a-1 of Bm for a >= 1 and g_0 = minus the sum of the rows.
// Returned as the 3x4 matrix of columns g_a.
Eigen::Matrix<double, 3, 4> shape_gradients(const Eigen::Matrix3d& Bm) {
  Eigen::Matrix<double, 3, 4> g;
  g.col(0) = -Bm.colwise().sum().transpose();
  for (int a = 1; a < 4; ++a) g.col(a) = Bm.row(a - 1).transpose();
  return g;
}
}  // namespace

std::vector<ElementRest> element_rest(const TetMesh& rest) {
  std::vector<ElementRest> out(static_cast<size_t>(rest.num_tets()));
  for (int t = 0; t < rest.num_tets(); ++t) {
    Eigen::Matrix3d dm;
    const Eigen::Vector3d x0 = rest.nodes.row(rest.tets(t, 0)).transpose();
    for (int k = 0; k < 3; ++k) dm.col(k) = rest.nodes.row(rest.tets(t, k + 1)).transpose() - x0;
    const double det = dm.determinant();
    RECOIL_CHECK(det > 0.0, "tet " << t << " has rest volume " << det / 6.0);
    out[static_cast<size_t>(t)] = {dm.inverse(), det / 6.0};
  }
  return out;
}

Eigen::Matrix3d deformation_gradient(const ElementRest& rest, const Vector12d& x) {
  Eigen::Matrix3d ds;
  for (int k = 0; k < 3; ++k) ds.col(k) = x.segment<3>(3 * (k + 1)) - x.segment<3>(0);
  return ds * rest.Bm;
}

ElementEval evaluate_element(MaterialModel model, const Lame& lame, const ElementRest& rest, const Vector12d& x,
                             bool want_hessian, bool project) {
  const Eigen::Matrix3d F = deformation_gradient(rest, x);
  const HessianMode mode = !want_hessian ? HessianMode::none : project ? HessianMode::projected : HessianMode::exact;
  const DensityEval d = evaluate_density(model, F, lame, mode);
  const Eigen::Matrix<double, 3, 4> g = shape_gradients(rest.Bm);
  ElementEval out;
  out.energy = rest.volume * d.psi;
  // dE/dx_a = V P g_a.
  const Eigen::Matrix<double, 3, 4> grad = rest.volume * d.P * g;
  out.gradient = Eigen::Map<const Vector12d>(grad.data());
  if (!want_hessian) {
    out.hessian.setZero();
    return out;
  }
  // H_ab = V sum_jl g_a[j] g_b[l] C_jl with C_jl the 3x3 block (rows i, cols k)
  // of dP/dF at (i + 3j, k + 3l): G^T C G without multiplying G's zeros.
  Eigen::Matrix3d T[4][3];  // T[b][j] = sum_l g_b[l] C_jl
  for (int b = 0; b < 4; ++b)
    for (int j = 0; j < 3; ++j)
      T[b][j] = g(0, b) * d.dPdF.block<3, 3>(3 * j, 0) + g(1, b) * d.dPdF.block<3, 3>(3 * j, 3) +
                g(2, b) * d.dPdF.block<3, 3>(3 * j, 6);
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      const Eigen::Matrix3d h = rest.volume * (g(0, a) * T[b][0] + g(1, a) * T[b][1] + g(2, a) * T[b][2]);
      out.hessian.block<3, 3>(3 * a, 3 * b) = h;
      if (b != a) out.hessian.block<3, 3>(3 * b, 3 * a) = h.transpose();
    }
  return out;
}

}  // namespace recoil::sim
