// solve_contacts (contact_problem.h): dispatch to the method, time it and
// measure the common KKT residual.
#include <chrono>

#include "core/check.h"
#include "sim/solver/contact_problem.h"
#include "sim/solver/contact_rows_ops.h"
#include "sim/solver/cr_solver.h"
#include "sim/solver/kkt_residual.h"
#include "sim/solver/pgs_solver.h"

namespace recoil::sim {

const char* to_string(SolverMethod method) {
  switch (method) {
    case SolverMethod::cr: return "cr";
    case SolverMethod::cr_plain: return "cr_plain";
    case SolverMethod::pgs: return "pgs";
  }
  return "unknown";
}

const char* to_string(KrylovStart start) {
  switch (start) {
    case KrylovStart::first_solve: return "first solve";
    case KrylovStart::contact_switch: return "contact switch";
    case KrylovStart::mode_change: return "mode change";
    case KrylovStart::friction_update: return "friction update";
    case KrylovStart::new_contacts: return "new contacts";
    case KrylovStart::relinearization: return "relinearization";
    case KrylovStart::recheck: return "recheck";
    case KrylovStart::breakdown: return "breakdown";
    case KrylovStart::past_dimension: return "past dimension";
  }
  return "unknown";
}

ContactSolverStats solve_contacts(ContactProblem& problem, const ContactSolverSettings& settings,
                                  Eigen::VectorXd& dv, ContactLinearization* linearization) {
  RECOIL_CHECK(problem.A != nullptr);
  RECOIL_CHECK(problem.b.size() == problem.A->rows(), "b=" << problem.b.size() << " A=" << problem.A->rows());
  RECOIL_CHECK(problem.rows.size() == problem.states.size(),
               "rows=" << problem.rows.size() << " states=" << problem.states.size());
  for (const ContactRows& rows : problem.rows) {
    RECOIL_CHECK(rows.nodes.size() == rows.blocks.size());
    for (size_t i = 0; i < rows.nodes.size(); ++i)
      RECOIL_CHECK(rows.nodes[i] >= 0 && rows.nodes[i] < problem.A->block_rows() && (i == 0 || rows.nodes[i - 1] < rows.nodes[i]),
                   "contact node " << rows.nodes[i]);
  }
  const auto start = std::chrono::steady_clock::now();
  ContactSolverStats stats;
  if (settings.method == SolverMethod::pgs)
    solve_contacts_pgs(problem, settings, dv, linearization, stats);
  else
    solve_contacts_cr(problem, settings, settings.method == SolverMethod::cr, dv, linearization, stats);
  stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  stats.kkt = kkt_residual(problem, dv).max();
  if (settings.method == SolverMethod::pgs) stats.residual = stats.kkt;
  return stats;
}

}  // namespace recoil::sim
