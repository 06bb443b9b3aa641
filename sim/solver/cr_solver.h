#pragma once
// The preconditioned conjugate-residual active-set solver (the
// paper's Algorithm 1) on the masked saddle system
//   B(S) y = d,  y = [dv; f],  f = (lambda, gamma1, gamma2) per contact,
//   B(S) = [[A, -J^T S], [-S J, -(I - S)]],  d = [b + J_t^T g_kinetic; -S c],
// S selecting the active normal rows and the tangent rows of sticking
// contacts: an unselected row reads f = 0, so sizes never change and B
// stays symmetric. Only products with A and the per-contact blocks of J
// are used.
//
// The preconditioner is block Jacobi: per-contact blocks and block SSOR
// cost as much or more on the FEM contact bench
// (docs/decisions/009-contact-preconditioner.md).
#include <Eigen/Core>

#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// preconditioned = false is `cr_plain` (C = I). Fills every stats field but ms and kkt.
void solve_contacts_cr(ContactProblem& problem, const ContactSolverSettings& settings, bool preconditioned,
                       Eigen::VectorXd& dv, ContactLinearization* linearization, ContactSolverStats& stats);

}  // namespace recoil::sim
