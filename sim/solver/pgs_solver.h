#pragma once
// The classical baseline: projected Gauss-Seidel on the Delassus operator
// W = J A^-1 J^T, with A^-1 applied through a sparse LDL^T factorisation of
// A (one solve per constraint column). The friction cone is the exact
// circular one: each sweep projects a contact's tangent impulse onto the
// disk of radius mu_kinetic * lambda. PGS has a single cone, so it uses
// mu_kinetic: the law a sliding contact obeys; the static/kinetic hysteresis
// of mu_static > mu_kinetic is a state PGS cannot carry.
#include <Eigen/Core>

#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// Same outer loop as cr (new contacts, re-linearisation), same warm start.
// settings.tolerance bounds the largest impulse change of a sweep, scaled
// to a velocity by diag(W). Fills every stats field but ms and kkt;
// iterations counts sweeps.
void solve_contacts_pgs(ContactProblem& problem, const ContactSolverSettings& settings, Eigen::VectorXd& dv,
                        ContactLinearization* linearization, ContactSolverStats& stats);

}  // namespace recoil::sim
