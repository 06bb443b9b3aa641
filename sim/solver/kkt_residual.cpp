#include "sim/solver/kkt_residual.h"

#include <algorithm>
#include <cmath>

#include "core/check.h"
#include "sim/solver/contact_rows_ops.h"

namespace recoil::sim {

double KktResidual::max() const { return std::max({momentum, penetration, complementarity, friction}); }

namespace {

// Coulomb's law for a sliding contact, as a velocity: the impulse must be
// mu lambda opposite the slip u (direction error: contact_rows_ops.h), mu
// the static coefficient while the slip has not started.
double sliding_violation(const ContactRows& rows, const ContactState& s, const Eigen::Vector2d& u, double w_t) {
  const double mu = sliding_mu(rows, s);
  double err = mu * std::abs(s.lambda_kinetic - s.lambda) * w_t;
  if (s.impending) err = std::max(err, u.norm());
  if (mu > 0.0 && s.lambda > 0.0)
    err = std::max(err, slip_direction_error(mu * s.lambda * w_t, u, s.slip));
  return err;
}

}  // namespace

KktResidual kkt_residual(const ContactProblem& problem, const Eigen::VectorXd& dv) {
  const ProblemPreconditioner P(problem);
  return kkt_residual(problem, dv, P.get());
}

KktResidual kkt_residual(const ContactProblem& problem, const Eigen::VectorXd& dv, const MomentumPreconditioner& P) {
  RECOIL_CHECK(problem.A != nullptr && problem.rows.size() == problem.states.size());
  const BlockSparseMatrix& A = *problem.A;
  RECOIL_CHECK(dv.size() == A.rows() && problem.b.size() == A.rows());
  RECOIL_CHECK(static_cast<int>(P.diagonal_inverses().size()) == A.block_rows());

  KktResidual out;
  Eigen::VectorXd g;
  A.multiply(dv, g);
  g -= problem.b;
  for (size_t k = 0; k < problem.rows.size(); ++k) {
    const ContactRows& rows = problem.rows[k];
    const ContactState& s = problem.states[k];
    const Eigen::Vector3d w = effective_inverse_mass(rows, P);
    const double w_t = std::max(w[1], w[2]);
    const Eigen::Vector3d jdv = rows_times(rows, dv);
    const double slack = jdv[0] - rows.rhs_normal;
    const Eigen::Vector2d u = jdv.tail<2>() - rows.rhs_tangent;
    if (!rows.nodes.empty()) out.penetration = std::max(out.penetration, -slack);
    if (s.mode == ContactMode::inactive) continue;
    Eigen::Vector3d f;
    f << s.lambda, tangent_impulse(rows, s);
    add_rows_transpose_times(rows, -f, g);
    out.complementarity = std::max(out.complementarity, -s.lambda * w[0]);
    if (slack > 0.0 && s.lambda > 0.0) out.complementarity = std::max(out.complementarity, std::min(slack, s.lambda * w[0]));
    if (s.mode == ContactMode::sticking) {
      out.friction = std::max(out.friction, u.lpNorm<Eigen::Infinity>());
      out.friction = std::max(out.friction, (s.gamma.norm() - rows.mu_static * s.lambda) * w_t);
    } else {
      out.friction = std::max(out.friction, sliding_violation(rows, s, u, w_t));
    }
  }
  Eigen::VectorXd velocity_error(g.size());
  P.apply(g, velocity_error);
  out.momentum = velocity_error.lpNorm<Eigen::Infinity>();
  return out;
}

}  // namespace recoil::sim
