#include "sim/solver/constraint_evaluation.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/check.h"
#include "sim/solver/contact_rows_ops.h"

namespace recoil::sim {

void restart_lambda_window(ContactTrack& track, double lambda_kinetic) {
  track.lambdas.fill(0.0);
  track.lambdas[0] = lambda_kinetic;
  track.samples = 1;
}

void reset_lambda_window(ContactTrack& track, double lambda_kinetic, double alpha_theta) {
  restart_lambda_window(track, lambda_kinetic);
  track.alpha = alpha_theta;
  track.last_turn = 0;
  track.streak = 0;
  track.turned_slip.setZero();
  track.turned_u.setZero();
}

namespace {

// Angle (rad) from unit vector a to unit vector b, counter-clockwise
// positive; atan2 of (cross, dot) is exact near 0, where a cosine is not.
double signed_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

// The moving average of the last `window` normal impulses, `lambda` the newest.
double push_lambda(ContactTrack& track, double lambda, int window) {
  if (track.samples < window) {
    track.lambdas[static_cast<size_t>(track.samples++)] = lambda;
  } else {
    std::rotate(track.lambdas.begin(), track.lambdas.begin() + 1, track.lambdas.begin() + window);
    track.lambdas[static_cast<size_t>(window - 1)] = lambda;
  }
  double sum = 0.0;
  for (int i = 0; i < track.samples; ++i) sum += track.lambdas[static_cast<size_t>(i)];
  return sum / track.samples;
}

// What one evaluation reads besides the contact itself.
struct Evaluation {
  const ContactPolicy& policy;
  double eps2;     // m/s
  bool converged;  // y solves the current system
};

// A contact's proposed new state, multipliers and bookkeeping: applied only
// when `accept`, so a discarded proposal changes nothing.
struct Proposal {
  int contact = -1;    // index into the problem's contacts
  ContactState state;
  Eigen::Vector3d f;   // multipliers for y: (lambda, gamma) with gamma = 0 unless sticking
  ContactTrack track;
  bool mode_change = false;
  bool accept = false;
  double violation = 0.0;  // m/s: how far the contact is from its current mode's law (mode changes only)
};

Proposal unchanged(const ContactState& s, const ContactTrack& track, const Eigen::Vector3d& f) {
  return Proposal{-1, s, f, track, false, false};
}

// Proposal p switched off, `violation` m/s from the law.
void switch_off(Proposal& p, double violation) {
  p.state = ContactState{};
  p.f.setZero();
  p.mode_change = p.accept = true;
  p.violation = violation;
}

// Algorithm 2, lines 7-8 (seed): a penetrating inactive contact is activated,
// in kinetic friction, its slip along the tangential velocity u (none yet
// when u is below epsilon_2).
Proposal activate(const ContactState& s, const ContactTrack& track, const Eigen::Vector3d& f, double slack,
                  const Eigen::Vector2d& u, const Evaluation& e) {
  Proposal p = unchanged(s, track, f);
  p.state.mode = ContactMode::sliding;
  p.state.lambda_kinetic = 0.0;
  const double speed = u.norm();
  p.state.slip = speed > e.eps2 ? Eigen::Vector2d(u / speed) : Eigen::Vector2d::Zero();
  p.f.setZero();
  reset_lambda_window(p.track, 0.0, e.policy.alpha_theta);
  p.track.samples = 0;
  p.mode_change = p.accept = true;
  p.violation = -slack;
  return p;
}

// Algorithm 2, lines 11-13: a sticking contact whose friction impulse left
// the static cone slides, along -gamma, its lambda' starting at the current
// lambda. It breaks away only when the tangential residual u
// does not push along gamma: the rows' own correction would otherwise undo
// the step.
void update_static_friction(const ContactRows& rows, const Eigen::Vector2d& u, const Evaluation& e, double w_t,
                            Proposal& p) {
  const double lambda = p.f[0];
  const Eigen::Vector2d gamma = p.f.tail<2>();
  const double norm = gamma.norm();
  const double excess = (norm - rows.mu_static * std::max(lambda, 0.0)) * w_t;
  const bool can_stick = rows.mu_static > 0.0;
  if (can_stick && !(excess > e.eps2 && u.dot(gamma) <= e.eps2 * norm)) return;
  p.state.mode = ContactMode::sliding;
  p.state.slip = norm > 0.0 ? Eigen::Vector2d(-gamma / norm) : Eigen::Vector2d::Zero();
  p.state.lambda_kinetic = std::max(lambda, 0.0);
  p.state.gamma.setZero();
  p.f.tail<2>().setZero();
  reset_lambda_window(p.track, p.state.lambda_kinetic, e.policy.alpha_theta);
  p.mode_change = p.accept = true;
  p.violation = excess;
}

// Algorithm 2, lines 14-16: a sliding contact whose slip runs backwards
// (policy.reversal) sticks, its kinetic impulse becoming the static one. A
// slip turned less is a direction to follow: with an anisotropic W_tt the
// slip near the cone's rim points askew to the impulse until the direction
// has converged. An undirected slip sticks once u is below epsilon_2.
bool reverses(const ContactRows& rows, const ContactState& s, const Eigen::Vector2d& u, const Evaluation& e,
              Proposal& p) {
  const bool undirected = s.slip.squaredNorm() == 0.0;
  const double speed = u.norm();
  const bool reversed =
      undirected ? speed <= e.eps2 : (u.dot(s.slip) < -e.eps2 && u.dot(s.slip) < -e.policy.reversal * speed);
  const bool can_stick = rows.mu_static > 0.0;
  if (!can_stick || !reversed) return false;
  p.state.mode = ContactMode::sticking;
  p.f.tail<2>() = -rows.mu_kinetic * s.lambda_kinetic * s.slip;
  p.state.lambda_kinetic = 0.0;
  p.state.slip.setZero();
  p.mode_change = p.accept = true;
  p.violation = undirected ? e.eps2 : -u.dot(s.slip);
  return true;
}

// Algorithm 3, lines 6-8: turns the slip toward its aim, the slip this
// contact would have without its own friction, u + w_t mu lambda' slip (for
// an isolated contact the fixed point itself, one solve; aiming at u
// converges by the factor w_t mu lambda' / |u| per solve). Policy: the gain
// halves at a turn against the last one and doubles back after
// alpha_streak turns the same way; where the error is small and
// contracting only linearly (coupled to sticking neighbours), a bounded
// secant step on F(theta) = angle(u) - angle(slip) replaces the damped one.
// Returns the aim; `direction_error` (m/s) is the KKT measure of the
// current direction.
Eigen::Vector2d turn_slip(const ContactRows& rows, const ContactState& s, const Eigen::Vector2d& u, double w_t,
                          const Evaluation& e, Proposal& p, double& direction_error) {
  const ContactPolicy& policy = e.policy;
  const double speed = u.norm();
  Eigen::Vector2d aim = s.slip;
  if (!(speed > e.eps2)) return aim;
  const Eigen::Vector2d u_hat = u / speed;
  if (s.slip.squaredNorm() == 0.0) {  // undirected: take u's direction
    p.state.slip = aim = u_hat;
    return aim;
  }
  const double error_now = signed_angle(s.slip, u_hat);  // rad, from the slip to u
  if (!(std::abs(error_now) > policy.eps_theta)) return aim;  // line 6: theta below epsilon_theta
  // The same measure as the KKT residual's, on lambda'.
  direction_error = slip_direction_error(rows.mu_kinetic * p.state.lambda_kinetic * w_t, u, s.slip);
  const int turn = error_now > 0.0 ? 1 : -1;
  if (turn == -p.track.last_turn) {
    p.track.alpha *= 0.5;
    p.track.streak = 0;
  } else if (++p.track.streak >= policy.alpha_streak) {
    p.track.alpha = std::min(policy.alpha_theta, 2.0 * p.track.alpha);
    p.track.streak = 0;
  }
  p.track.last_turn = turn;
  const Eigen::Vector2d target = u + w_t * rows.mu_kinetic * s.lambda_kinetic * s.slip;
  aim = target.norm() > 0.0 ? Eigen::Vector2d(target.normalized()) : u_hat;
  Eigen::Vector2d moved = s.slip + p.track.alpha * (aim - s.slip);  // lines 7-8
  if (p.track.turned_slip.squaredNorm() > 0.0) {
    const double error_before = signed_angle(p.track.turned_slip, p.track.turned_u);
    const double turned = signed_angle(p.track.turned_slip, s.slip);
    const double ratio = error_now / error_before;
    if (std::abs(error_now) < policy.secant_range && std::abs(turned) > policy.eps_theta && ratio > 0.0 &&
        ratio < policy.secant_contraction) {
      const double reach = policy.secant_reach * std::abs(error_now);
      const double step = std::clamp(-error_now * turned / (error_now - error_before), -reach, reach);
      if (step * error_now > 0.0) moved = Eigen::Rotation2Dd(step) * s.slip;
    }
  }
  p.track.turned_slip = s.slip;
  p.track.turned_u = u_hat;
  if (moved.norm() > 0.0) p.state.slip = moved.normalized();
  return aim;
}

// Algorithm 3 (UpdateKineticFriction) for a sliding contact at a converged
// evaluation: lambda' becomes the moving average of lambda (lines 4-5), the
// slip turns (lines 6-8, turn_slip), and line 9's impulse -mu lambda' slip
// is what the state now holds. Accepted when it moves the kinetic impulse
// by more than epsilon_2 (Algorithm 2, line 18). Policy: while the damped
// change is below that and the law is still off by more, the step grows to
// registered_change epsilon_2 toward the whole way (lambda' = lambda, slip
// = aim), never past it: the solve would not iterate for a smaller change,
// the next evaluation would see the same u, and a decayed gain would hide
// a wrong direction; the whole way at once swings coupled contacts
// period-2. A contact whose whole way changes nothing keeps its state, and
// the end of the solve reports it.
void update_kinetic_friction(const ContactRows& rows, const ContactState& s, const Eigen::Vector2d& u, double w_t,
                             const Evaluation& e, Proposal& p) {
  const double lambda_now = std::max(p.f[0], 0.0);
  p.state.lambda_kinetic = push_lambda(p.track, lambda_now, e.policy.lambda_window);
  double direction_error = 0.0;
  const Eigen::Vector2d aim = turn_slip(rows, s, u, w_t, e, p, direction_error);
  const auto impulse_change = [&](const ContactState& next) {
    return rows.mu_kinetic * w_t *
           std::max((next.lambda_kinetic * next.slip - s.lambda_kinetic * s.slip).norm(),
                    std::abs(next.lambda_kinetic - s.lambda_kinetic));
  };
  const double magnitude_error = rows.mu_kinetic * std::abs(lambda_now - s.lambda_kinetic) * w_t;
  double applied = impulse_change(p.state);
  if (applied <= e.eps2 && std::max(magnitude_error, direction_error) > e.eps2) {
    ContactState whole = p.state;
    whole.lambda_kinetic = lambda_now;
    whole.slip = aim;
    const double whole_change = impulse_change(whole);
    if (whole_change > e.eps2) {
      const double t = std::min(1.0, e.policy.registered_change * e.eps2 / whole_change);
      p.state.lambda_kinetic = s.lambda_kinetic + t * (lambda_now - s.lambda_kinetic);
      restart_lambda_window(p.track, p.state.lambda_kinetic);
      // Along the arc, not the chord: a normalised chord point turns by less
      // than t of the angle, and a wide turn then fell below epsilon_2.
      if (s.slip.squaredNorm() > 0.0 && aim.squaredNorm() > 0.0)
        p.state.slip = Eigen::Rotation2Dd(t * signed_angle(s.slip, aim)) * s.slip;
      else if (aim.squaredNorm() > 0.0)
        p.state.slip = aim.normalized();
      p.track.alpha = std::max(p.track.alpha, t);
      applied = impulse_change(p.state);
    }
  }
  const bool undirected = s.slip.squaredNorm() == 0.0;
  p.accept = applied > e.eps2 || (undirected && p.state.slip.squaredNorm() > 0.0);
}

// Algorithm 2, lines 5-17, for a contact whose normal row is active, at
// normal slack J_n dv - rhs and tangential velocity u = J_t dv - rhs_t (m/s).
// Policy: friction changes only at converged evaluations; a frozen contact
// (past max_flips) keeps its mode, except that one pulling at a converged
// evaluation (a near-duplicate of an active neighbour: their lambdas grow
// without bound in opposite directions) is let go for the rest of the solve.
Proposal evaluate_active(const ContactRows& rows, const ContactState& s, const ContactTrack& track,
                         const Eigen::Vector3d& f, double slack, const Eigen::Vector2d& u, bool frozen,
                         const Evaluation& e) {
  Proposal p = unchanged(s, track, f);
  const double pull = -f[0] * track.w[0];  // m/s: how hard lambda pulls (positive) or pushes
  if (!frozen && slack >= -e.eps2 && pull > e.eps2) {  // lines 5-6: separating and pulling
    switch_off(p, pull);
    return p;
  }
  if (frozen && e.converged && pull > e.eps2) {
    switch_off(p, pull);
    p.track.locked_off = true;
    return p;
  }
  const double w_t = std::max(track.w[1], track.w[2]);
  if (s.mode == ContactMode::sticking) {  // lines 10-13
    if (!frozen && e.converged) update_static_friction(rows, u, e, w_t, p);
    return p;
  }
  if (!e.converged) return p;  // u is not yet trustworthy
  if (!frozen && reverses(rows, s, u, e, p)) return p;  // lines 14-16
  const bool frictionless = rows.mu_kinetic <= 0.0;
  if (!frictionless) update_kinetic_friction(rows, s, u, w_t, e, p);  // line 17, frozen or not
  return p;
}

// Policy (change_share, parallel) on the proposals of one evaluation: mode
// changes are ranked by violation and only those within change_share of
// the worst are applied; of the activations left, the deepest goes first
// and one whose normal row is within `parallel` of a row already taken
// waits. Mid-solve the active rows count as taken too; at a converged
// evaluation they do not, or a contact beside a loaded one could never
// come on. `proposals` holds the proposing contacts only, in ascending
// contact order.
void hold_back(const ContactProblem& problem, const std::vector<ContactTrack>& tracks, const MomentumPreconditioner& P,
               const Evaluation& e, std::vector<Proposal>& proposals) {
  double worst = 0.0;  // the largest violation among proposed mode changes, m/s
  for (const Proposal& p : proposals)
    if (p.mode_change) worst = std::max(worst, p.violation);
  for (Proposal& p : proposals)
    if (p.mode_change && p.violation < e.policy.change_share * worst) p.accept = false;
  std::vector<int> order;  // indices into `proposals`: the activations, deepest first
  std::vector<int> taken;  // contact indices: the normal rows already on
  if (!e.converged)
    for (size_t k = 0; k < problem.states.size(); ++k)
      if (problem.states[k].mode != ContactMode::inactive) taken.push_back(static_cast<int>(k));
  for (size_t i = 0; i < proposals.size(); ++i) {
    const Proposal& p = proposals[i];
    const bool active = problem.states[static_cast<size_t>(p.contact)].mode != ContactMode::inactive;
    if (!active && p.accept && p.mode_change) order.push_back(static_cast<int>(i));
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return proposals[static_cast<size_t>(a)].violation > proposals[static_cast<size_t>(b)].violation;
  });
  for (int i : order) {
    Proposal& p = proposals[static_cast<size_t>(i)];
    const int k = p.contact;
    const ContactRows& rows = problem.rows[static_cast<size_t>(k)];
    const double w_k = tracks[static_cast<size_t>(k)].w[0];
    for (int t : taken) {
      // The cosine of the two normal rows in the P_A^-1 metric.
      const double w_t = tracks[static_cast<size_t>(t)].w[0];
      const double product = normal_rows_product(rows, problem.rows[static_cast<size_t>(t)], P);
      if (w_k > 0.0 && w_t > 0.0 && product > e.policy.parallel * std::sqrt(w_k * w_t)) {
        p.accept = false;
        break;
      }
    }
    if (p.accept) taken.push_back(k);
  }
}

}  // namespace

// Algorithm 2 (EvaluateConstraints): every contact's proposal (lines 3-17),
// the policy's hold-back, then the accepted changes applied (lines 18-21);
// the solver rebuilds the right-hand side (line 22).
EvaluationChanges evaluate_constraints(ContactProblem& problem, std::vector<ContactTrack>& tracks, Eigen::VectorXd& y,
                                       const MomentumPreconditioner& P, const ContactSolverSettings& settings,
                                       bool converged) {
  const int m = static_cast<int>(problem.rows.size());
  const int n = static_cast<int>(y.size()) - 3 * m;
  RECOIL_CHECK(n >= 0 && static_cast<int>(tracks.size()) == m && static_cast<int>(problem.states.size()) == m);
  RECOIL_CHECK(settings.policy.lambda_window >= 1 && settings.policy.lambda_window <= kMaxLambdaWindow,
               "lambda_window " << settings.policy.lambda_window);
  const Evaluation e{settings.policy, settings.constraint_tolerance, converged};
  const Eigen::VectorXd dv = y.head(n);
  std::vector<Proposal> proposals;  // only the contacts that propose a change, in ascending order
  for (int k = 0; k < m; ++k) {
    const ContactRows& rows = problem.rows[static_cast<size_t>(k)];
    const ContactState& s = problem.states[static_cast<size_t>(k)];
    const ContactTrack& track = tracks[static_cast<size_t>(k)];
    const Eigen::Vector3d f = y.segment<3>(n + 3 * k);
    if (rows.nodes.empty()) continue;  // touches only fixed DoF: nothing to solve for
    Proposal p;
    if (s.mode == ContactMode::inactive) {
      // Most candidates are inactive and stay so: their normal row decides,
      // and the tangent rows are read only for one that comes on. A contact
      // let go after freezing stays off.
      const double slack = normal_row_times(rows, dv) - rows.rhs_normal;
      if (!(slack < -e.eps2) || track.locked_off) continue;  // not penetrating (a NaN slack included)
      p = activate(s, track, f, slack, rows_times(rows, dv).tail<2>() - rows.rhs_tangent, e);
    } else {
      // The selected rows' own yield counts as motion (ContactSoftness).
      const Eigen::Vector3d yield = problem.softness.yield(track.w, f, rows);
      const Eigen::Vector3d jdv = rows_times(rows, dv);
      const double slack = jdv[0] + yield[0] - rows.rhs_normal;
      Eigen::Vector2d u = jdv.tail<2>() - rows.rhs_tangent;
      if (s.mode == ContactMode::sticking) u += yield.tail<2>();
      p = evaluate_active(rows, s, track, f, slack, u, track.flips >= settings.max_flips, e);
    }
    p.contact = k;
    if (p.accept) proposals.push_back(p);
  }
  hold_back(problem, tracks, P, e, proposals);
  EvaluationChanges changed;
  for (const Proposal& p : proposals) {
    if (!p.accept) continue;
    const int k = p.contact;
    problem.states[static_cast<size_t>(k)] = p.state;
    ContactTrack& track = tracks[static_cast<size_t>(k)];
    track = p.track;
    y.segment<3>(n + 3 * k) = p.f;
    if (p.mode_change) {
      ++track.flips;
      ++changed.mode_changes;
    } else {
      ++changed.friction_updates;
    }
  }
  return changed;
}

}  // namespace recoil::sim
