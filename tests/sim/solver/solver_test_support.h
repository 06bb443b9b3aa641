#pragma once
// Helpers for the contact solver tests: a brute-force reference for
// frictionless problems and a one-line solve.
#include <Eigen/Dense>
#include <optional>

#include "sim/solver/contact_problem.h"
#include "sim/solver/contact_rows_ops.h"

namespace recoil::sim::solver_test {

inline constexpr double kG = 9.81;        // m/s^2
inline constexpr double kH = 1.0 / 60.0;  // s: the time step of the solver tests' problems
inline constexpr SolverMethod kMethods[] = {SolverMethod::cr, SolverMethod::cr_plain, SolverMethod::pgs};

// Settings with both tolerances (m/s) at `tolerance` and a generous cap.
inline ContactSolverSettings tight(SolverMethod method, double tolerance = 1e-11, int max_iterations = 200000) {
  ContactSolverSettings s;
  s.method = method;
  s.tolerance = tolerance;
  s.constraint_tolerance = tolerance;
  s.max_iterations = max_iterations;
  return s;
}

struct Solution {
  Eigen::VectorXd dv;
  std::vector<ContactState> states;
  ContactSolverStats stats;
};

// Solves a copy of `problem` (warm states as given).
inline Solution solve_copy(const ContactProblem& problem, const ContactSolverSettings& settings) {
  ContactProblem copy = problem;
  Solution out;
  out.stats = solve_contacts(copy, settings, out.dv);
  out.states = copy.states;
  return out;
}

struct Reference {
  Eigen::VectorXd dv;
  Eigen::VectorXd lambda;
};

// The normal rows of every contact as one dense #contacts by #DoF matrix.
inline Eigen::MatrixXd dense_normal_rows(const ContactProblem& problem) {
  const int m = static_cast<int>(problem.rows.size());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, problem.b.size());
  for (int k = 0; k < m; ++k) {
    const ContactRows& rows = problem.rows[static_cast<size_t>(k)];
    for (size_t i = 0; i < rows.nodes.size(); ++i) J.block<1, 3>(k, 3 * rows.nodes[i]) = rows.blocks[i].row(0);
  }
  return J;
}

// Frictionless reference: tries every active set of the normal rows and
// returns the one whose equality-constrained solution is feasible with
// non-negative multipliers (unique for SPD A and independent rows).
inline std::optional<Reference> brute_force_normal(const ContactProblem& problem) {
  const Eigen::MatrixXd A = Eigen::MatrixXd(problem.A->to_eigen());
  const int n = static_cast<int>(A.rows());
  const int m = static_cast<int>(problem.rows.size());
  const Eigen::MatrixXd J = dense_normal_rows(problem);
  Eigen::VectorXd c(m);
  for (int k = 0; k < m; ++k) c[k] = problem.rows[static_cast<size_t>(k)].rhs_normal;
  for (int set = 0; set < (1 << m); ++set) {
    std::vector<int> active;
    for (int k = 0; k < m; ++k)
      if (set & (1 << k)) active.push_back(k);
    const int a = static_cast<int>(active.size());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + a, n + a);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + a);
    K.topLeftCorner(n, n) = A;
    rhs.head(n) = problem.b;
    for (int i = 0; i < a; ++i) {
      K.block(0, n + i, n, 1) = -J.row(active[static_cast<size_t>(i)]).transpose();
      K.block(n + i, 0, 1, n) = -J.row(active[static_cast<size_t>(i)]);
      rhs[n + i] = -c[active[static_cast<size_t>(i)]];
    }
    const Eigen::VectorXd y = K.fullPivLu().solve(rhs);
    const Eigen::VectorXd dv = y.head(n);
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
    for (int i = 0; i < a; ++i) lambda[active[static_cast<size_t>(i)]] = y[n + i];
    const Eigen::VectorXd slack = J * dv - c;
    if (lambda.minCoeff() >= -1e-10 && slack.minCoeff() >= -1e-10) return Reference{dv, lambda};
  }
  return std::nullopt;
}

}  // namespace recoil::sim::solver_test
