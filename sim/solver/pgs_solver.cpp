#include "sim/solver/pgs_solver.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "core/check.h"
#include "sim/solver/contact_rows_ops.h"

namespace recoil::sim {

namespace {

class PgsSolver {
 public:
  PgsSolver(ContactProblem& problem, const ContactSolverSettings& settings, ContactLinearization* linearization,
            ContactSolverStats& stats)
      : m_problem(problem), m_settings(settings), m_linearization(linearization), m_stats(stats),
        m_n(problem.A->rows()) {
    m_ldlt.compute(problem.A->to_eigen());
    RECOIL_CHECK(m_ldlt.info() == Eigen::Success, "A is not SPD");
    m_dv_free = m_ldlt.solve(problem.b);
  }

  void run(Eigen::VectorXd& dv);

 private:
  int contacts() const { return static_cast<int>(m_problem.rows.size()); }
  void build_operator();
  double sweep();
  void write_states();

  ContactProblem& m_problem;
  const ContactSolverSettings& m_settings;
  ContactLinearization* m_linearization;
  ContactSolverStats& m_stats;
  int m_n;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> m_ldlt;
  Eigen::VectorXd m_dv_free;  // A^-1 b
  Eigen::MatrixXd m_G;        // #DoF by 3 #contacts: A^-1 J^T
  Eigen::MatrixXd m_W;        // 3 #contacts square: J A^-1 J^T
  Eigen::VectorXd m_f;        // impulses (lambda, gamma) per contact
  Eigen::VectorXd m_u;        // J dv for the current impulses
};

void PgsSolver::build_operator() {
  const int m = contacts();
  m_G.resize(m_n, 3 * m);
  for (int k = 0; k < m; ++k)
    for (int r = 0; r < 3; ++r) {
      Eigen::VectorXd column = Eigen::VectorXd::Zero(m_n);
      add_rows_transpose_times(m_problem.rows[static_cast<size_t>(k)], Eigen::Vector3d::Unit(r), column);
      m_G.col(3 * k + r) = m_ldlt.solve(column);
    }
  m_W.resize(3 * m, 3 * m);
  for (int c = 0; c < 3 * m; ++c) {
    const Eigen::VectorXd column = m_G.col(c);
    for (int k = 0; k < m; ++k) m_W.block<3, 1>(3 * k, c) = rows_times(m_problem.rows[static_cast<size_t>(k)], column);
  }
  m_u.resize(3 * m);
  for (int k = 0; k < m; ++k) m_u.segment<3>(3 * k) = rows_times(m_problem.rows[static_cast<size_t>(k)], m_dv_free);
  m_u.noalias() += m_W * m_f;
}

// One Gauss-Seidel sweep in contact order; returns the largest impulse
// change as a velocity (m/s).
double PgsSolver::sweep() {
  double change = 0.0;
  for (int k = 0; k < contacts(); ++k) {
    const ContactRows& rows = m_problem.rows[static_cast<size_t>(k)];
    if (rows.nodes.empty()) continue;
    const Eigen::Matrix3d Wkk = m_W.block<3, 3>(3 * k, 3 * k);
    if (!(Wkk(0, 0) > 0.0)) continue;
    const Eigen::Vector3d old = m_f.segment<3>(3 * k);
    Eigen::Vector3d u = m_u.segment<3>(3 * k);
    const double lambda = std::max(0.0, old[0] - (u[0] - rows.rhs_normal) / Wkk(0, 0));
    u += Wkk.col(0) * (lambda - old[0]);
    Eigen::Vector2d gamma = Eigen::Vector2d::Zero();
    const double radius = rows.mu_kinetic * lambda;
    if (radius > 0.0) {
      // A scalar step 1 / lambda_max(W_tt), not the 2x2 solve: the Euclidean
      // projection then has its fixed point where the slip opposes gamma
      // (maximal dissipation); a matrix step would skew the direction.
      const Eigen::Matrix2d Wtt = Wkk.bottomRightCorner<2, 2>();
      const double top = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(Wtt, Eigen::EigenvaluesOnly).eigenvalues()[1];
      if (top > 0.0) gamma = old.tail<2>() - (u.tail<2>() - rows.rhs_tangent) / top;
      const double norm = gamma.norm();
      if (norm > radius) gamma *= radius / norm;
    }
    const Eigen::Vector3d next(lambda, gamma[0], gamma[1]);
    const Eigen::Vector3d delta = next - old;
    if (delta.squaredNorm() == 0.0) continue;
    m_f.segment<3>(3 * k) = next;
    m_u.noalias() += m_W.middleCols<3>(3 * k) * delta;
    change = std::max(change, delta.cwiseAbs().cwiseProduct(Wkk.diagonal()).maxCoeff());
  }
  return change;
}

// A contact whose tangent impulse lies on the cone's rim is sliding against
// it; inside, it sticks.
void PgsSolver::write_states() {
  for (int k = 0; k < contacts(); ++k) {
    const ContactRows& rows = m_problem.rows[static_cast<size_t>(k)];
    ContactState& s = m_problem.states[static_cast<size_t>(k)];
    const Eigen::Vector3d f = m_f.segment<3>(3 * k);
    s = ContactState{};
    if (!(f[0] > 0.0)) continue;
    s.lambda = f[0];
    const Eigen::Vector2d gamma = f.tail<2>();
    const double radius = rows.mu_kinetic * f[0];
    if (rows.mu_static > 0.0 && gamma.norm() < radius * (1.0 - 1e-9)) {
      s.mode = ContactMode::sticking;
      s.gamma = gamma;
      ++m_stats.sticking;
    } else {
      s.mode = ContactMode::sliding;
      s.lambda_kinetic = f[0];
      const double norm = gamma.norm();
      s.slip = norm > 0.0 ? Eigen::Vector2d(-gamma / norm) : Eigen::Vector2d::Zero();
      ++m_stats.sliding;
    }
    ++m_stats.active;
  }
}

void PgsSolver::run(Eigen::VectorXd& dv) {
  const int m = contacts();
  m_f = Eigen::VectorXd::Zero(3 * m);
  for (int k = 0; k < m; ++k) {
    const ContactState& s = m_problem.states[static_cast<size_t>(k)];
    if (s.mode == ContactMode::inactive) continue;
    m_f[3 * k] = std::max(s.lambda, 0.0);
    m_f.segment<2>(3 * k + 1) = tangent_impulse(m_problem.rows[static_cast<size_t>(k)], s);
  }
  build_operator();
  m_stats.converged = false;
  bool relinearized_ok = false;
  while (m_stats.iterations < m_settings.max_iterations) {
    const double change = sweep();
    ++m_stats.iterations;
    if (change >= m_settings.tolerance) continue;
    dv = m_dv_free + m_G * m_f;
    if (m_linearization == nullptr) {
      m_stats.converged = true;
      break;
    }
    const int added = m_linearization->add_new_contacts(dv, m_problem);
    if (added > 0) {
      relinearized_ok = false;
      m_stats.new_contacts += added;
      m_f.conservativeResize(3 * contacts());
      m_f.tail(3 * added).setZero();
      for (int k = contacts() - added; k < contacts(); ++k) m_problem.states[static_cast<size_t>(k)] = ContactState{};
      build_operator();
      continue;
    }
    // Done once a re-linearisation moved nothing beyond epsilon_2 and the
    // sweeps on its rows (whose normals may have turned) settled again.
    if (relinearized_ok) {
      m_stats.converged = true;
      break;
    }
    if (m_stats.relinearizations >= m_settings.max_relinearizations) break;  // not converged
    const double moved = m_linearization->relinearize(dv, m_problem);
    ++m_stats.relinearizations;
    relinearized_ok = moved <= m_settings.constraint_tolerance;
    build_operator();
  }
  dv = m_dv_free + m_G * m_f;
  m_stats.residual = 0.0;
  write_states();
}

}  // namespace

void solve_contacts_pgs(ContactProblem& problem, const ContactSolverSettings& settings, Eigen::VectorXd& dv,
                        ContactLinearization* linearization, ContactSolverStats& stats) {
  PgsSolver solver(problem, settings, linearization, stats);
  solver.run(dv);
}

}  // namespace recoil::sim
