#pragma once
// The iterate closest to a solution that a CR solve (cr_solver.h) has met,
// handed back when the solve ends unconverged: at the cap, y is wherever the
// last restart left it, mid-way through a Krylov solve for an active set the
// next evaluation may change again. Candidates are the warm start, every
// solved iterate and every restart's iterate (a capped solve may never solve
// a system between its mid-solve switches), measured by the KKT residual,
// which counts the momentum error too, on the rows as they are now
// (docs/decisions/019-capped-solve-hand-back.md has the measurements).
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/contact_problem.h"

namespace recoil::sim {

class BestIterate {
 public:
  // n: #DoF; P: the P_A^-1 the KKT residual measures velocities with.
  BestIterate(ContactProblem& problem, int n, const MomentumPreconditioner& P)
      : m_problem(problem), m_n(n), m_P(P) {}

  // The KKT residual (kkt_residual.h), m/s, of iterate y (#DoF + 3 #contacts)
  // with the friction states `states` (as many as the problem has contacts,
  // or fewer: contacts added since count as inactive), on the current rows.
  // `states` may be problem.states itself.
  double kkt_of(const Eigen::VectorXd& y, const std::vector<ContactState>& states);

  // y with the problem's current states: kept if it beats the best so far.
  // Returns its KKT residual, m/s.
  double offer(const Eigen::VectorXd& y);

  // The rows changed (new contacts, re-linearisation): the best iterate is
  // measured again on them, so later ones compete on the same rows.
  void remeasure();

  // When the best beats y: y and problem.states become it (contacts added
  // since: inactive) and true is returned; the caller rebuilds what depends
  // on them.
  bool restore_if_better(Eigen::VectorXd& y);

 private:
  ContactProblem& m_problem;
  int m_n;
  const MomentumPreconditioner& m_P;
  Eigen::VectorXd m_y;
  std::vector<ContactState> m_states;
  double m_kkt = std::numeric_limits<double>::infinity();
};

}  // namespace recoil::sim
