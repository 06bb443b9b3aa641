#pragma once
// EvaluateConstraints and UpdateKineticFriction (the paper's
// Algorithms 2 and 3) on the CR solver's iterate y = [dv; f], f holding
// (lambda, gamma1, gamma2) per contact. Every threshold is a velocity in m/s
// (epsilon_2): an impulse is turned into one by the row's effective inverse
// mass w = diag(J P_A^-1 J^T), so a change counts only when it moves some
// contact by more than epsilon_2.
//
// Choices for Algorithm 3 (the paper gives no values):
// - lambda' is the simple moving average of the last kLambdaWindow normal
//   impulses seen at evaluations: a short window damps the lambda <-> lambda'
//   feedback of coupled contacts and still reaches lambda exactly in
//   kLambdaWindow evaluations once lambda has settled;
// - the slip direction turns toward its aim, the direction of u with the
//   contact's own kinetic impulse taken out (u + w_t mu lambda' slip: the
//   fixed point for an isolated contact), with gain alpha (at most
//   kAlphaTheta = 1) whenever slip and u differ by more than kEpsTheta.
//   Strongly coupled contacts overshoot (period-2 swings of the direction
//   between solves), so a contact's gain halves each time an accepted turn
//   reverses the previous one and doubles back (to at most kAlphaTheta)
//   after kAlphaStreak = 4 accepted turns the same way (after 2 it cycled:
//   halve, double, halve on random coupled problems). The angle is measured
//   with atan2(cross, dot), exact near 0 (cos(1e-9) is 1.0 in double, so a
//   cosine test turned rounding noise into turns of random sign). kEpsTheta
//   = 1e-10 rad only keeps round-off out; the real threshold is epsilon_2,
//   twice: the law must be off by more than it (the direction error is
//   slip_direction_error of contact_rows_ops.h, the KKT residual's measure),
//   and the change made must exceed it, or the solve cannot see
//   it; a damped step too small to register grows to kRegisteredChange
//   epsilon_2 toward the whole way, so a decayed gain cannot hide a wrong
//   direction either (the .cpp says why). A rejected proposal leaves the
//   contact's state and track as they were;
// - the aim's fixed point is the slip's own only for an isolated contact;
//   beside sticking neighbours it is reached linearly (rollers, resolution
//   3, step 27: the KKT residual fell by 0.74 per solve, 20 solves after
//   each re-linearisation). Where the direction error is below kSecantRange
//   and error_now / error_before (at the contact's last turn) lies in
//   (0, kSecantContraction), the turn is a secant step on F(theta) =
//   angle(u) - angle(slip) from those two turns instead, toward u and at
//   most kSecantReach times the error. A heuristic with a weak basis:
//   - over the rollers at omega 5, 6, 7 and resolutions 3, 4, 5 (150 steps
//     each), with the solve's stop at KKT <= epsilon_2 (cr_solver.cpp): 470
//     capped steps against 538, no worst KKT above 0.6 m/s (four runs above
//     1 before, up to 18), and resolution 5 no longer carries the block up
//     round a roller;
//   - but the remembered turn is in the contact's tangent frame, which a
//     re-linearisation moves (and tangent_basis jumps across n.z = 0, where
//     the rollers' normals lie). Forgetting it at each re-linearisation
//     made that sweep 526 capped steps with worst KKT up to 1.9e4 and an
//     inverted block; bounding error_before instead of error_now, 485 and
//     up to 11 m/s. The gain above is within the scatter of such changes;
//     the secant alone (without the KKT stop) inverted the block at
//     resolutions 3 and 5. Rebasing the remembered turn into the new frame
//     is the untried correct form;
//   - an earlier secant, unbounded, made the lattice of convergence_test 23
//     solves instead of 25 but broke convergence elsewhere;
// - sticking <-> sliding changes, like Algorithm 3, are made only at
//   converged evaluations: decided on the half-converged gamma and u of
//   mid-solve evaluations they cycled on stiff resting bodies (boundary
//   contacts at the cone's rim: 200-2000 restarts, frozen contacts and
//   kkt ~2e-4 m/s on the FEM bench); mid-solve evaluations still switch
//   contacts on and off;
// - kinetic -> static needs the slip to run backwards by more than
//   acos(-kReversal) = 120 degrees off the slip direction; smaller turns are
//   followed as direction changes.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "sim/fem/momentum_preconditioner.h"
#include "sim/solver/contact_problem.h"

namespace recoil::sim {

inline constexpr int kLambdaWindow = 3;
inline constexpr double kAlphaTheta = 1.0;
inline constexpr double kEpsTheta = 1e-10;  // rad
inline constexpr double kReversal = 0.5;
inline constexpr int kAlphaStreak = 4;
inline constexpr double kChangeShare = 0.9;
inline constexpr double kParallel = 0.9;  // cosine above which two normal rows count as one (see below)
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
// the accepted changes to problem.states and to the multipliers in y.
// P is P_A^-1 of problem.A (momentum_preconditioner.h): the metric in which
// rows count as parallel (below).
// The worst violations first: each proposed mode change has a violation in
// m/s (activation: -slack; separation: -lambda w_n; sticking to sliding:
// (|gamma| - mu_s lambda) w_t; sliding to sticking: the reversed slip
// speed), and only those at least kChangeShare of the largest in this
// evaluation are applied; the rest wait for a later evaluation (updates of
// a sliding contact's lambda' and direction are not mode changes: the share
// does not hold them back). Switching on every violated contact at once over-constrains a
// body landing on a corner or a curved face: on the bunny pile, 80 of 927
// candidates came on together where the solution has 6, the next solves
// switched them off down to 4, the one after on again to 82, and the active
// set cycled until the iteration cap; the deepest first (then the next
// deepest, solve by solve) reached the 6-contact solution, and a body
// landing flat still switches all its equally deep contacts on at once.
// Rigid bodies resting on each other need the same for the other changes:
// their face contacts are redundant, the split of lambda and gamma among
// them is whatever the Krylov iterate makes it, and a converged solve of a
// 5-box stack proposed separating two contacts, sliding two and sticking
// six at once; applied together, the next solves cycled through them to
// the cap (9 of the first 15 steps unconverged once the redundant crossings
// of face diagonals were gone, narrow_phase.h; with them, the extra rows
// had happened to hide it). The largest change alone, then the next, lands
// where pgs does: 28 active contacts, every step converged. The largest is
// taken over the whole problem, so a big change on one body holds back
// small ones elsewhere for an evaluation or two.
// Nearly parallel rows are not switched on together: of the activations
// that pass the share, the deepest comes first, and one whose normal row
// has a cosine above kParallel with a row already taken (in the P_A^-1
// metric, which is exact for rigid bodies) waits. Mid-solve, the active
// rows count as taken; at a converged evaluation only this evaluation's
// activations do. Why: a rigid body on a plane has at most three
// independent normal rows (n.v and two tilts), so a fourth contact makes
// the equality system singular, and on a curved surface (gaps not affine
// in position) inconsistent. A faceted ball rolling down an incline
// (2562 vertices) passes its pivot to the next vertex: three neighbours
// ahead came on together (cosines 0.98-0.99 with each other and the
// sticking pivot), their right-hand sides were met only by impulses of
// +-40 N s, and the ball was flung at 11 m/s. One at a time, the solve
// that follows says whether the next is still needed. Without the
// mid-solve part, three contacts about a pivot still cycled on and off
// through max_flips (up to 9 of 120 steps unconverged over six sphere
// variants; with it, none).
// The rigid box stack, whose corner rows have cosines -0.5..0.25, still
// switches a flat landing on at once; it stands for kParallel from 0.7 to
// 0.99 and falls at 0.5. The cosine is signed: rows pointing against each
// other (a body pinched from two sides) hold it from both sides, and
// neither can stand in for the other.
// Contacts past `max_flips` mode changes are frozen in the active state:
// an inactive one may still activate, an active one keeps its friction
// mode and does not separate mid-solve. One frozen contact that pulls
// (lambda < -epsilon_2) on a converged system is switched off and stays off
// for the rest of the solve: held on, it was a near-duplicate of a sliding
// neighbour whose lambda grew against it without bound (bunny pile: +8 and
// -9 N s after 3000 iterations), and the step blew up. If it penetrates at
// the end, the solve reports itself unconverged.
// Friction mode changes and Algorithm 3 run only when `converged` (y solves
// the current system): lambda' and the slip direction are a fixed-point
// iteration over whole solves, and feeding it the half-converged u of
// mid-solve evaluations made it chase its own tail (restart cycles on
// random coupled problems). Returns how many contacts changed, mode changes
// and friction updates apart (the solver's stats tell the restarts apart).
struct EvaluationChanges {
  int mode_changes = 0;      // contacts switched on or off, or between sticking and sliding
  int friction_updates = 0;  // sliding contacts whose lambda' or slip direction moved, mode kept
  int total() const { return mode_changes + friction_updates; }
};
EvaluationChanges evaluate_constraints(ContactProblem& problem, std::vector<ContactTrack>& tracks, Eigen::VectorXd& y,
                                       const MomentumPreconditioner& P, double eps2, int max_flips,
                                       bool converged);

}  // namespace recoil::sim
