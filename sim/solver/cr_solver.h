#pragma once
// The preconditioned conjugate-residual active-set solver (METHOD.md
// sections 3-5, seed/ Algorithm 1) on the masked saddle system
//   B(S) y = d,  y = [dv; f],  f = (lambda, gamma1, gamma2) per contact,
//   B(S) = [[A, -J^T S], [-S J, -(I - S)]],  d = [b + J_t^T g_kinetic; -S c],
// S selecting the active normal rows and the tangent rows of sticking
// contacts: an unselected row reads f = 0, so sizes never change and B
// stays symmetric (prototypes/cr_active_set.py). Only products with A and
// the per-contact blocks of J are used.
#include <Eigen/Core>

#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// preconditioned = false is `cr_plain` (C = I). Fills every stats field but ms and kkt.
void solve_contacts_cr(ContactProblem& problem, const ContactSolverSettings& settings, bool preconditioned,
                       Eigen::VectorXd& dv, ContactLinearization* linearization, ContactSolverStats& stats);

}  // namespace recoil::sim
