#include "sim/fem/pcg.h"

#include <cmath>

namespace recoil::sim {

PcgResult solve_pcg(const BlockSparseMatrix& A, const MomentumPreconditioner& P, const Eigen::VectorXd& b,
                    Eigen::VectorXd& x, const PcgSettings& settings) {
  auto precondition = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
    out.resize(in.size());
    P.apply(in, out);
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
