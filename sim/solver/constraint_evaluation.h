#pragma once
// EvaluateConstraints and UpdateKineticFriction (the paper's Algorithms 2
// and 3) on the CR solver's iterate y = [dv; f], f holding (lambda, gamma1,
// gamma2) per contact. The .cpp has one function per algorithm, commented
// with the seed's line numbers; everything they add to the seed is a field
// of ContactPolicy (contact_policy.h). Every threshold is a velocity in m/s
// (epsilon_2): an impulse becomes one through the row's effective inverse
// mass w = diag(J P_A^-1 J^T).
#include <Eigen/Core>
#include <vector>

#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/contact_policy.h"
#include "sim/solver/contact_problem.h"
#include "sim/solver/friction_acceleration.h"

namespace recoil::sim {

// Evaluates every contact of `problem` at y (#DoF + 3 #contacts); applies
// the accepted changes to problem.states and to the multipliers in y.
// inverse_masses: per contact, its three rows' effective_inverse_mass. P is
// P_A^-1 of problem.A, the metric in which rows count as parallel. From
// `settings`: epsilon_2 (constraint_tolerance) and the policy. Friction mode
// changes and Algorithm 3 run only when `converged` (y solves the current
// system). Returns how many contacts changed, mode changes and friction
// updates apart.
struct EvaluationChanges {
  int mode_changes = 0;      // contacts switched on or off, or between sticking and sliding
  int friction_updates = 0;  // sliding contacts given a new lambda' or slip direction, mode kept
  int total() const { return mode_changes + friction_updates; }
};
// A converged evaluation moves the sliding contacts' lambda' and slip
// directions through `acceleration`, which keeps its pairs from one such
// evaluation to the next (none given: a fresh one, the damped plain step).
EvaluationChanges evaluate_constraints(ContactProblem& problem, const std::vector<Eigen::Vector3d>& inverse_masses,
                                       Eigen::VectorXd& y, const MomentumPreconditioner& P,
                                       const ContactSolverSettings& settings, bool converged,
                                       FrictionAcceleration* acceleration = nullptr);

}  // namespace recoil::sim
