#pragma once
// EvaluateConstraints and UpdateKineticFriction (the paper's Algorithms 2
// and 3) on the CR solver's iterate y = [dv; f], f holding (lambda, gamma1,
// gamma2) per contact. Every threshold is a velocity in m/s (epsilon_2): an
// impulse becomes one through the row's effective inverse mass
// w = diag(J P_A^-1 J^T). Algorithm 3's free choices (a moving-average
// lambda', a damped slip-direction turn with a secant step, the reversal
// angle) and the rules beyond Algorithm 2 (friction changes only when
// converged, worst violations first, parallel rows one at a time, frozen
// contacts) are explained with their measurements in
// docs/decisions/008-contact-evaluation-rules.md.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/contact_problem.h"

namespace recoil::sim {

inline constexpr int kLambdaWindow = 3;       // normal impulses averaged into lambda'
inline constexpr double kAlphaTheta = 1.0;    // the largest slip-direction gain
inline constexpr double kEpsTheta = 1e-10;    // rad: direction changes below this are round-off
inline constexpr double kReversal = 0.5;      // -cosine past which a reversed slip sticks (120 degrees)
inline constexpr int kAlphaStreak = 4;        // same-way turns after which a halved gain doubles back
inline constexpr double kChangeShare = 0.9;   // mode changes within this share of the worst are applied
inline constexpr double kParallel = 0.9;      // cosine above which two normal rows count as one
inline constexpr double kRegisteredChange = 2.0;  // in epsilon_2: the smallest friction step taken
inline constexpr double kSecantContraction = 0.95;  // secant only when error_now / error_before is below this
inline constexpr double kSecantReach = 8.0;         // a secant turn is at most this many times the error
inline constexpr double kSecantRange = 0.1;         // rad: the secant only for direction errors below this

// Solver-side bookkeeping of one contact, beside its ContactState.
struct ContactTrack {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();  // effective inverse mass of the three rows, 1/kg
  std::array<double, kLambdaWindow> lambdas{};  // recent normal impulses of a sliding contact, N s
  int samples = 0;                              // filled entries of `lambdas`
  int flips = 0;                                // mode changes in this solve
  bool locked_off = false;                      // frozen, then let go for pulling: inactive for the rest of the solve
  double alpha = kAlphaTheta;                   // direction gain, halved at each overshoot
  int last_turn = 0;                            // sign of the last direction turn (+1 counter-clockwise)
  int streak = 0;                               // accepted turns the same way since alpha last changed
  // The slip direction and the direction of u at the last accepted turn (zero: none yet), for the secant.
  Eigen::Vector2d turned_slip = Eigen::Vector2d::Zero(), turned_u = Eigen::Vector2d::Zero();
};

// Starts the moving average of a sliding contact at `lambda_kinetic`, and
// its direction gain afresh.
void reset_lambda_window(ContactTrack& track, double lambda_kinetic);
// Starts the moving average only, keeping the direction gain.
void restart_lambda_window(ContactTrack& track, double lambda_kinetic);

// Evaluates every contact of `problem` at y (#DoF + 3 #contacts); applies
// the accepted changes to problem.states and to the multipliers in y. P is
// P_A^-1 of problem.A, the metric in which rows count as parallel. Proposed
// mode changes are ranked by their violation in m/s and only those within
// kChangeShare of the worst are applied; an activation whose normal row is
// within kParallel of a row already taken waits. Contacts past `max_flips`
// mode changes are frozen active; a frozen one that pulls at a converged
// evaluation is switched off for the rest of the solve. Friction mode
// changes and Algorithm 3 run only when `converged` (y solves the current
// system). Returns how many contacts changed, mode changes and friction
// updates apart.
struct EvaluationChanges {
  int mode_changes = 0;      // contacts switched on or off, or between sticking and sliding
  int friction_updates = 0;  // sliding contacts whose lambda' or slip direction moved, mode kept
  int total() const { return mode_changes + friction_updates; }
};
EvaluationChanges evaluate_constraints(ContactProblem& problem, std::vector<ContactTrack>& tracks, Eigen::VectorXd& y,
                                       const MomentumPreconditioner& P, double eps2, int max_flips,
                                       bool converged);

}  // namespace recoil::sim
