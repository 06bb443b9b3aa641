#pragma once
// The preconditioned conjugate-residual active-set solver (METHOD.md
// sections 3-5, seed/ Algorithm 1) on the masked saddle system
//   B(S) y = d,  y = [dv; f],  f = (lambda, gamma1, gamma2) per contact,
//   B(S) = [[A, -J^T S], [-S J, -(I - S)]],  d = [b + J_t^T g_kinetic; -S c],
// S selecting the active normal rows and the tangent rows of sticking
// contacts: an unselected row reads f = 0, so sizes never change and B
// stays symmetric (prototypes/cr_active_set.py). Only products with A and
// the per-contact blocks of J are used.
//
// The preconditioner (issue #5; `recoil_bench solver_fem`: a tetrahedralized
// 0.5 m cube, rho 1000, h = 1/60 s, 1029 and 3993 DoF, 49 and 121 bottom
// contacts, E 1e5..1e7, sliding at 0.2 m/s or resting; tolerance 1e-6 m/s,
// cold start; ratios below are cr_plain / cr iterations and time ratios):
// - block Jacobi (P_A = 3x3 diagonal blocks, P_S = diag(J P_A^-1 J^T)), the
//   default: 1.9-6.1x fewer iterations than cr_plain when sliding (the gain
//   grows with E), 2.4-17x when resting except one (E 1e5, 3993 DoF,
//   resting: 0.56x, more restarts than cr_plain). What it removes is the
//   spread of the diagonal (mass + h^2 stiffness per node); what it leaves
//   is the spectrum of D^-1 A itself (h^2 E / (rho dx^2) ~ 10^2..10^4 here)
//   and the restarts: every accepted change of the active set or friction
//   state throws the Krylov space away (40-65 per sliding solve, 200-900 for
//   stiff resting bodies whose boundary contacts hover at the cone's rim),
//   and each restart pays the ~sqrt(condition) iterations again. No P_A
//   fixes the second part; fewer state changes would.
// - contact_blocks (P_S = each contact's 3x3 block J_k P_A^-1 J_k^T on its
//   selected rows): identical when every contact slides (one selected row);
//   when resting 0.65-0.92x the time of block Jacobi in five of six
//   problems but 8x in one (E 1e7, 1029 DoF: 9120 restarts), so not the
//   default.
// - ssor (block SSOR, omega 1.5, for P_A): 1.4-1.8x fewer iterations than
//   block Jacobi when sliding, but each application costs about one product
//   with A: 0.6-1.25x the time sliding, 1.3-16x resting (more restarts). It
//   does not pay for itself, so it is not the default.
#include <Eigen/Core>

#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// preconditioned = false is `cr_plain` (C = I). Fills every stats field but ms and kkt.
void solve_contacts_cr(ContactProblem& problem, const ContactSolverSettings& settings, bool preconditioned,
                       Eigen::VectorXd& dv, ContactLinearization* linearization, ContactSolverStats& stats);

}  // namespace recoil::sim
