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

void reset_lambda_window(ContactTrack& track, double lambda_kinetic) {
  restart_lambda_window(track, lambda_kinetic);
  track.alpha = kAlphaTheta;
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

double push_lambda(ContactTrack& track, double lambda) {
  if (track.samples < kLambdaWindow) {
    track.lambdas[static_cast<size_t>(track.samples++)] = lambda;
  } else {
    std::rotate(track.lambdas.begin(), track.lambdas.begin() + 1, track.lambdas.end());
    track.lambdas.back() = lambda;
  }
  double sum = 0.0;
  for (int i = 0; i < track.samples; ++i) sum += track.lambdas[static_cast<size_t>(i)];
  return sum / track.samples;
}

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

// Algorithm 2 for one contact whose normal row is active. u: tangential
// velocity J_t dv - rhs_tangent, m/s.
Proposal evaluate_active(const ContactRows& rows, const ContactState& s, const ContactTrack& track,
                         const Eigen::Vector3d& f, double slack, const Eigen::Vector2d& u, double eps2, bool frozen,
                         bool converged) {
  Proposal p{-1, s, f, track, false, false};
  const double lambda = f[0];
  const Eigen::Vector2d gamma = f.tail<2>();
  const double w_t = std::max(track.w[1], track.w[2]);
  const bool can_stick = rows.mu_static > 0.0;
  if (!frozen && slack >= -eps2 && lambda * track.w[0] < -eps2) {  // separating
    p.state = ContactState{};
    p.f.setZero();
    p.mode_change = p.accept = true;
    p.violation = -lambda * track.w[0];
    return p;
  }
  if (frozen && converged && lambda * track.w[0] < -eps2) {
    // A frozen contact that pulls on a solved system holds the others
    // against it (a near-duplicate of an active neighbour: its lambda and
    // the neighbour's grow without bound in opposite directions). It is
    // let go, and kept off for the rest of the solve.
    p.state = ContactState{};
    p.f.setZero();
    p.track.locked_off = true;
    p.mode_change = p.accept = true;
    p.violation = -lambda * track.w[0];
    return p;
  }
  if (s.mode == ContactMode::sticking) {
    const double norm = gamma.norm();
    const double excess = (norm - rows.mu_static * std::max(lambda, 0.0)) * w_t;
    // Break away only when the tangential residual does not push along gamma:
    // the step would otherwise be undone by the rows' own correction.
    if (!frozen && converged && (!can_stick || (excess > eps2 && u.dot(gamma) <= eps2 * norm))) {
      p.state.mode = ContactMode::sliding;
      p.state.slip = norm > 0.0 ? Eigen::Vector2d(-gamma / norm) : Eigen::Vector2d::Zero();
      p.state.lambda_kinetic = std::max(lambda, 0.0);
      p.state.gamma.setZero();
      p.f.tail<2>().setZero();
      reset_lambda_window(p.track, p.state.lambda_kinetic);
      p.mode_change = p.accept = true;
      p.violation = excess;
    }
    return p;
  }
  // Sliding.
  const bool undirected = s.slip.squaredNorm() == 0.0;
  // Reversal: the slip clearly runs backwards (more than kReversal off
  // -slip). A slip turned sideways is a direction to follow, not a stop: with
  // an anisotropic W_tt the slip of a contact near the cone's rim points
  // askew to the friction impulse until the direction has converged.
  const double speed = u.norm();
  const bool reversed = undirected ? speed <= eps2 : (u.dot(s.slip) < -eps2 && u.dot(s.slip) < -kReversal * speed);
  if (!frozen && converged && can_stick && reversed) {
    p.state.mode = ContactMode::sticking;
    p.f.tail<2>() = -rows.mu_kinetic * s.lambda_kinetic * s.slip;
    p.state.lambda_kinetic = 0.0;
    p.state.slip.setZero();
    p.mode_change = p.accept = true;
    p.violation = undirected ? eps2 : -u.dot(s.slip);
    return p;
  }
  if (rows.mu_kinetic <= 0.0 || !converged) return p;  // frictionless, or u not yet trustworthy
  // Algorithm 3: UpdateKineticFriction.
  const double lambda_now = std::max(lambda, 0.0);
  p.state.lambda_kinetic = push_lambda(p.track, lambda_now);
  Eigen::Vector2d aim = s.slip;   // the direction the slip turns toward
  double direction_error = 0.0;   // m/s, see below
  if (speed > eps2) {
    const Eigen::Vector2d u_hat = u / speed;
    if (undirected) {
      p.state.slip = aim = u_hat;
    } else {
      const double error_now = signed_angle(s.slip, u_hat);  // rad, from the slip to u
      if (std::abs(error_now) > kEpsTheta) {
        // The same measure as the KKT residual's, on lambda'.
        direction_error = slip_direction_error(rows.mu_kinetic * p.state.lambda_kinetic * w_t, u, s.slip);
        // A turn against the previous one is an overshoot: halve the gain;
        // kAlphaStreak turns the same way: the gain is too timid, double it.
        const int turn = error_now > 0.0 ? 1 : -1;
        if (turn == -p.track.last_turn) {
          p.track.alpha *= 0.5;
          p.track.streak = 0;
        } else if (++p.track.streak >= kAlphaStreak) {
          p.track.alpha = std::min(kAlphaTheta, 2.0 * p.track.alpha);
          p.track.streak = 0;
        }
        p.track.last_turn = turn;
        // Aim at the slip this contact would have without its own friction,
        // u + w_t mu lambda' slip: for an isolated contact (isotropic w_t)
        // that is the fixed point itself (one solve), whereas aiming at u
        // converges by the factor w_t mu lambda' / |u| per solve (0.37 for
        // the particle of slip_direction_test). Coupled contacts still
        // converge only linearly (the lattice of convergence_test: ~25
        // solves for a warm start 0.1 rad off), hence the secant below.
        const Eigen::Vector2d target = u + w_t * rows.mu_kinetic * s.lambda_kinetic * s.slip;
        aim = target.norm() > 0.0 ? Eigen::Vector2d(target.normalized()) : u_hat;
        Eigen::Vector2d moved = s.slip + p.track.alpha * (aim - s.slip);
        // Coupled to sticking neighbours, a contact's u turns with its own
        // slip, and the aim converges only linearly (rollers: the error
        // shrank by 0.74 per solve, 20 solves after each re-linearisation).
        // Where this turn and the last show such a contraction on a small
        // error, the secant on F(theta) = angle(u) - angle(slip) steps to
        // its root instead (header: the bounds, and what it was measured on).
        if (p.track.turned_slip.squaredNorm() > 0.0) {
          const double error_before = signed_angle(p.track.turned_slip, p.track.turned_u);
          const double turned = signed_angle(p.track.turned_slip, s.slip);
          const double ratio = error_now / error_before;
          if (std::abs(error_now) < kSecantRange && std::abs(turned) > kEpsTheta && ratio > 0.0 &&
              ratio < kSecantContraction) {
            const double reach = kSecantReach * std::abs(error_now);
            const double step = std::clamp(-error_now * turned / (error_now - error_before), -reach, reach);
            if (step * error_now > 0.0) moved = Eigen::Rotation2Dd(step) * s.slip;
          }
        }
        p.track.turned_slip = s.slip;
        p.track.turned_u = u_hat;
        if (moved.norm() > 0.0) p.state.slip = moved.normalized();
      }
    }
  }
  // What the proposal changes, as a velocity: the kinetic impulse it moves
  // into the right-hand side through w_t, and lambda' on its own (an
  // undirected slip carries no impulse yet, but lambda' must track lambda
  // for when it does). A change below epsilon_2 moves no contact by
  // epsilon_2: the solve may not even iterate, and the next evaluation sees
  // the same u. Accepted anyway, such changes repeated with no iterations
  // between (jelly-stack example: 4000 restarts in one step). So only a
  // change above epsilon_2 is accepted. When the damped step is below it
  // while the law is still off by more (the window moves lambda' by a third
  // of lambda - oldest sample per evaluation; a decayed gain turns the slip
  // by a fraction of the way: the rollers' first step once ended
  // "converged" with a Coulomb error of 1.5e-4 m/s), the step grows to
  // kRegisteredChange epsilon_2 toward the whole way (lambda' = lambda,
  // slip = aim), never past it. Not the whole way at once: coupled contacts
  // then swing period-2 again (cr_plain on the FEM cube of
  // convergence_test never converged). A contact whose whole way changes
  // nothing (frozen sliding while its slip runs backwards: the aim is its
  // own slip) keeps its state, and the end of the solve reports it.
  const auto impulse_change = [&](const ContactState& next) {
    return rows.mu_kinetic * w_t *
           std::max((next.lambda_kinetic * next.slip - s.lambda_kinetic * s.slip).norm(),
                    std::abs(next.lambda_kinetic - s.lambda_kinetic));
  };
  const double magnitude_error = rows.mu_kinetic * std::abs(lambda_now - s.lambda_kinetic) * w_t;
  double applied = impulse_change(p.state);
  if (applied <= eps2 && std::max(magnitude_error, direction_error) > eps2) {
    ContactState whole = p.state;
    whole.lambda_kinetic = lambda_now;
    whole.slip = aim;
    const double whole_change = impulse_change(whole);
    if (whole_change > eps2) {
      const double t = std::min(1.0, kRegisteredChange * eps2 / whole_change);
      p.state.lambda_kinetic = s.lambda_kinetic + t * (lambda_now - s.lambda_kinetic);
      restart_lambda_window(p.track, p.state.lambda_kinetic);
      const Eigen::Vector2d moved = s.slip + t * (aim - s.slip);
      if (moved.norm() > 0.0) p.state.slip = moved.normalized();
      p.track.alpha = std::max(p.track.alpha, t);
      applied = impulse_change(p.state);
    }
  }
  p.accept = applied > eps2 || (undirected && p.state.slip.squaredNorm() > 0.0);
  return p;
}

// Of the activations accepted in one evaluation, the deepest goes first;
// one whose normal row is within kParallel of a row already taken waits for
// a later evaluation (the header says why). Mid-solve, the active rows count
// as taken too; at a converged evaluation they do not, or a contact beside
// a loaded one could never come on. `proposals` holds the proposing
// contacts only, in ascending contact order.
void hold_back_parallel_activations(const ContactProblem& problem, const std::vector<ContactTrack>& tracks,
                                    const MomentumPreconditioner& P, bool converged,
                                    std::vector<Proposal>& proposals) {
  std::vector<int> order;  // indices into `proposals`: the activations, deepest first
  std::vector<int> taken;  // contact indices: the normal rows already on
  if (!converged)
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
      if (w_k > 0.0 && w_t > 0.0 && product > kParallel * std::sqrt(w_k * w_t)) {
        p.accept = false;
        break;
      }
    }
    if (p.accept) taken.push_back(k);
  }
}

}  // namespace

EvaluationChanges evaluate_constraints(ContactProblem& problem, std::vector<ContactTrack>& tracks, Eigen::VectorXd& y,
                                       const MomentumPreconditioner& P, double eps2, int max_flips,
                                       bool converged) {
  const int m = static_cast<int>(problem.rows.size());
  const int n = static_cast<int>(y.size()) - 3 * m;
  RECOIL_CHECK(n >= 0 && static_cast<int>(tracks.size()) == m && static_cast<int>(problem.states.size()) == m);
  const Eigen::VectorXd dv = y.head(n);
  // Only the contacts that propose a change, in ascending order: most
  // candidates are inactive and stay so.
  std::vector<Proposal> proposals;
  double worst = 0.0;  // the largest violation among proposed mode changes, m/s
  for (int k = 0; k < m; ++k) {
    const ContactRows& rows = problem.rows[static_cast<size_t>(k)];
    const ContactState& s = problem.states[static_cast<size_t>(k)];
    const ContactTrack& track = tracks[static_cast<size_t>(k)];
    const Eigen::Vector3d f = y.segment<3>(n + 3 * k);
    Proposal p;
    if (rows.nodes.empty()) continue;  // touches only fixed DoF: nothing to solve for
    const bool frozen = track.flips >= max_flips;
    if (s.mode == ContactMode::inactive) {
      // Most candidates are inactive and stay so: their normal row decides,
      // and the tangent rows are read only for one that comes on.
      const double slack = normal_row_times(rows, dv) - rows.rhs_normal;
      // Activation is allowed even past max_flips: freezing happens in the active state.
      if (slack < -eps2 && !track.locked_off) {  // penetrating: activate, sliding
        const Eigen::Vector2d u = rows_times(rows, dv).tail<2>() - rows.rhs_tangent;
        p = Proposal{k, s, f, track, false, false};
        p.state.mode = ContactMode::sliding;
        p.state.lambda_kinetic = 0.0;
        const double speed = u.norm();
        p.state.slip = speed > eps2 ? Eigen::Vector2d(u / speed) : Eigen::Vector2d::Zero();
        p.f.setZero();
        reset_lambda_window(p.track, 0.0);
        p.track.samples = 0;
        p.mode_change = p.accept = true;
        p.violation = -slack;
      }
    } else {
      // The selected rows' own yield counts as motion (ContactSoftness).
      const Eigen::Vector3d yield = problem.softness.yield(track.w, f, rows);
      const Eigen::Vector3d jdv = rows_times(rows, dv);
      const double slack = jdv[0] + yield[0] - rows.rhs_normal;
      Eigen::Vector2d u = jdv.tail<2>() - rows.rhs_tangent;
      if (s.mode == ContactMode::sticking) u += yield.tail<2>();
      p = evaluate_active(rows, s, track, f, slack, u, eps2, frozen, converged);
      p.contact = k;
    }
    if (!p.accept) continue;
    if (p.mode_change) worst = std::max(worst, p.violation);
    proposals.push_back(p);
  }
  // Mode changes only when among the worst (header).
  for (Proposal& p : proposals)
    if (p.mode_change && p.violation < kChangeShare * worst) p.accept = false;
  hold_back_parallel_activations(problem, tracks, P, converged, proposals);
  // Apply the accepted proposals.
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
