#pragma once
// The end of a CR solve (cr_solver.h): the iterate y = [dv (#DoF); f (3 per
// contact)] read back into the contacts' states, and the counts the stats
// report about them. Kept out of the iteration's file (cr_solver.cpp), which
// uses only take_multipliers, to measure candidate iterates on the way.
#include <Eigen/Core>

#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// Copies an active contact k's multipliers out of y (n = #DoF) into s:
// lambda, and gamma when sticking (zero otherwise).
void take_multipliers(const Eigen::VectorXd& y, int n, int k, ContactState& s);

// Writes the final y into problem.states (inactive contacts reset, active
// ones take their multipliers) and fills stats.active / sticking / sliding.
void hand_back_states(ContactProblem& problem, const Eigen::VectorXd& y, ContactSolverStats& stats);

}  // namespace recoil::sim
