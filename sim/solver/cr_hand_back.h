#pragma once
// The end of a CR solve (cr_solver.h): the iterate y = [dv (#DoF); f (3 per
// contact)] read back into the contacts' states, and the counts the stats
// report about them. Kept out of the iteration's file (cr_solver.cpp), which
// uses only take_multipliers, to measure candidate iterates on the way.
#include <Eigen/Core>
#include <vector>

#include "sim/solver/constraint_evaluation.h"
#include "sim/solver/contact_problem.h"

namespace recoil::sim {

// Copies an active contact k's multipliers out of y (n = #DoF) into s:
// lambda, and gamma when sticking (zero otherwise).
void take_multipliers(const Eigen::VectorXd& y, int n, int k, ContactState& s);

// Writes the final y into problem.states (inactive contacts reset, active
// ones take their multipliers) and fills stats.active / sticking / sliding /
// frozen. Clears stats.converged when the answer is not a solution after
// all: a contact let go for pulling while frozen that now penetrates, or a
// frozen contact that kept a mode its own law rejects (pulling, sticking
// outside the cone, sliding backwards) by more than epsilon_2.
void hand_back_states(ContactProblem& problem, const std::vector<ContactTrack>& tracks, const Eigen::VectorXd& y,
                      const ContactSolverSettings& settings, ContactSolverStats& stats);

}  // namespace recoil::sim
