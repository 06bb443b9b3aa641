#include "sim/fem/element.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/LU>

#include "core/check.h"

namespace recoil::sim {

namespace {
// dF/dx as a 9x12 matrix: vec(F)_(i+3j) depends on node a's coordinate i
// through g_a[j], with g_a = row a-1 of Bm for a >= 1 and g_0 = -sum of rows.
Eigen::Matrix<double, 9, 12> dF_dx(const Eigen::Matrix3d& Bm) {
  Eigen::Matrix<double, 3, 4> g;
  g.col(0) = -Bm.colwise().sum().transpose();
  for (int a = 1; a < 4; ++a) g.col(a) = Bm.row(a - 1).transpose();
  Eigen::Matrix<double, 9, 12> G = Eigen::Matrix<double, 9, 12>::Zero();
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) G(i + 3 * j, 3 * a + i) = g(j, a);
  return G;
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
  DensityEval d = evaluate_density(model, F, lame, want_hessian);
  const Eigen::Matrix<double, 9, 12> G = dF_dx(rest.Bm);
  ElementEval out;
  out.energy = rest.volume * d.psi;
  out.gradient = rest.volume * G.transpose() * Eigen::Map<const Vector9d>(d.P.data());
  if (want_hessian) {
    if (project) project_psd(d.dPdF);
    out.hessian = rest.volume * G.transpose() * d.dPdF * G;
  } else {
    out.hessian.setZero();
  }
  return out;
}

}  // namespace recoil::sim
