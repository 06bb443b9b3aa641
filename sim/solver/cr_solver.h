#pragma once
// The preconditioned conjugate-residual active-set solver (the
// paper's Algorithm 1) on the masked saddle system
//   B(S) y = d,  y = [dv; f],  f = (lambda, gamma1, gamma2) per contact,
//   B(S) = [[A, -J^T S], [-S J, -(I - S) - S K]],  d = [b + J_t^T g_kinetic; -S c],
// S selecting the active normal rows and the tangent rows of sticking
// contacts, K the rows' diagonal compliance (ContactSoftness in
// contact_problem.h): an unselected row reads f = 0, so sizes never change
// and B stays symmetric. Only products with A and
// the per-contact blocks of J are used.
//
// The preconditioner, measured with P_A = the diagonal blocks alone, before
// the rigid-mode term of momentum_preconditioner.h (the bench's problems
// still leave ContactProblem::preconditioner null; `recoil_bench solver_fem`: a tetrahedralized
// 0.5 m cube, rho 1000, h = 1/60 s, 1029 and 3993 DoF, 49 and 121 bottom
// contacts, E 1e5..1e7, sliding at 0.2 m/s or resting; tolerance 1e-6 m/s,
// cold start; times on the shared 2-core machine, +-30% noise):
// - block Jacobi (P_A = 3x3 diagonal blocks, P_S = diag(J P_A^-1 J^T)), the
//   default: 2.1-6.6x fewer iterations than cr_plain when sliding, 1.9-15.6x
//   when resting (the gain grows with E), 1.4-14x less time; 3.9-11.7x
//   faster than pgs at 3993 DoF. What it removes is the spread of the
//   diagonal (mass + h^2 stiffness per node); what it leaves is the
//   spectrum of D^-1 A itself (h^2 E / (rho dx^2) ~ 10^2..10^4 here) and the
//   restarts: every accepted change of the active set or friction state
//   throws the Krylov space away (41-55 per sliding solve, 24-461 resting),
//   and each restart pays the ~sqrt(condition) iterations again. No P_A
//   fixes that part; fewer state changes would. ContactSolverStats::starts
//   counts the solves by cause (`recoil_bench contact` prints them): on the
//   rollers, 97% of the iterations re-solve after a change, ~30 solves per
//   step of ~76 iterations each (besides ~18 rechecks of no iterations).
// - contact_blocks (P_S = each contact's 3x3 block J_k P_A^-1 J_k^T on its
//   selected rows): identical when every contact slides (one selected row);
//   resting, 0.87-0.92x the iterations of block Jacobi but more restarts in
//   four of six problems, 0.95-1.5x the time, so not the default.
// - ssor (block SSOR, omega 1.5, for P_A): 1.4-1.6x fewer iterations than
//   block Jacobi when sliding, but each application costs about one product
//   with A: 0.8-1.3x the time sliding, 1.2-11.5x resting (more restarts). It
//   does not pay for itself, so it is not the default.
#include <Eigen/Core>

#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// preconditioned = false is `cr_plain` (C = I). Fills every stats field but ms and kkt.
void solve_contacts_cr(ContactProblem& problem, const ContactSolverSettings& settings, bool preconditioned,
                       Eigen::VectorXd& dv, ContactLinearization* linearization, ContactSolverStats& stats);

}  // namespace recoil::sim
