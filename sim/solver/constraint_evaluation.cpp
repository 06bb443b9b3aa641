#include "sim/solver/constraint_evaluation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <Eigen/Geometry>

#include "core/check.h"
#include "sim/solver/contact_rows_ops.h"
#include "sim/solver/dependent_rows.h"
#include "sim/solver/taken_normal_rows.h"

namespace recoil::sim {

namespace {

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
  bool mode_change = false;
  bool accept = false;
  double depth = 0.0;  // m/s: how far an activated contact penetrates (the hold-back takes the deepest first)
};

Proposal unchanged(const ContactState& s, const Eigen::Vector3d& f) { return Proposal{-1, s, f, false, false}; }

// Proposal p switched off.
void switch_off(Proposal& p) {
  p.state = ContactState{};
  p.f.setZero();
  p.mode_change = p.accept = true;
}

// Algorithm 2, lines 7-8 (seed): a penetrating inactive contact is activated,
// in kinetic friction, its slip along the tangential velocity u (none yet
// when u is below epsilon_2, or when its sides were at rest: reverses()).
Proposal activate(const ContactRows& rows, const ContactState& s, const Eigen::Vector3d& f, double slack,
                  const Eigen::Vector2d& u, const Evaluation& e) {
  Proposal p = unchanged(s, f);
  p.state.mode = ContactMode::sliding;
  p.state.lambda_kinetic = 0.0;
  const double speed = u.norm();
  p.state.slip = speed > e.eps2 && !sides_at_rest(rows, e.eps2) ? Eigen::Vector2d(u / speed) : Eigen::Vector2d::Zero();
  p.f.setZero();
  p.mode_change = p.accept = true;
  p.depth = -slack;
  return p;
}

// Sticking contact p slides along -gamma, its lambda' starting at lambda.
void break_away(const ContactRows& rows, Proposal& p) {
  const Eigen::Vector2d gamma = p.f.tail<2>();
  const double norm = gamma.norm();
  p.state.mode = ContactMode::sliding;
  p.state.slip = norm > 0.0 ? Eigen::Vector2d(-gamma / norm) : Eigen::Vector2d::Zero();
  p.state.lambda_kinetic = std::max(p.f[0], 0.0);
  p.state.impending = rows.mu_static > rows.mu_kinetic;
  p.state.gamma.setZero();
  p.f.tail<2>().setZero();
  p.mode_change = p.accept = true;
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
  break_away(rows, p);
}

// Algorithm 2, lines 14-16: a sliding contact whose slip runs backwards
// (policy.reversal) sticks, its kinetic impulse becoming the static one. A
// slip turned less is a direction to follow: with an anisotropic W_tt the
// slip near the cone's rim points askew to the impulse until the direction
// has converged. An undirected slip (activated without one) sticks once u is
// below epsilon_2, or when its two sides were at rest relative to each other
// as the step began (-rhs_tangent, the slip at dv = 0, below epsilon_2):
// static friction holds such a contact until the cone test lets it break
// away (directed along u, it could stick only by reversing, and a body at
// rest on a slope steeper than mu_k but within mu_s would slide).
bool reverses(const ContactRows& rows, const ContactState& s, const Eigen::Vector2d& u, const Evaluation& e,
              Proposal& p) {
  const bool undirected = s.slip.squaredNorm() == 0.0;
  const double speed = u.norm();
  const bool reversed = undirected ? speed <= e.eps2 || sides_at_rest(rows, e.eps2)
                                   : (u.dot(s.slip) < -e.eps2 && u.dot(s.slip) < -e.policy.reversal * speed);
  const bool can_stick = rows.mu_static > 0.0;
  if (!can_stick || !reversed) return false;
  p.state.mode = ContactMode::sticking;
  p.f.tail<2>() = tangent_impulse(rows, s);
  p.state.impending = false;
  p.state.lambda_kinetic = 0.0;
  p.state.slip.setZero();
  p.mode_change = p.accept = true;
  return true;
}

// Algorithm 3 for a sliding contact without a direction yet (activated
// while u was below epsilon_2): lambda' is the current lambda (lines 4-5),
// and the slip takes u's direction once u is above epsilon_2 (lines 6-8).
void direct_slip(const ContactRows& rows, const Eigen::Vector2d& u, double w_t, const Evaluation& e, Proposal& p) {
  const double lambda = std::max(p.f[0], 0.0);
  const double speed = u.norm();
  const bool directed = speed > e.eps2;
  if (directed) p.state.slip = u / speed;
  p.accept = directed || sliding_mu(rows, p.state) * w_t * std::abs(lambda - p.state.lambda_kinetic) > e.eps2;
  p.state.lambda_kinetic = lambda;
}

// Algorithm 2, lines 5-17, for a contact whose normal row is active, at
// normal slack J_n dv - rhs and tangential velocity u = J_t dv - rhs_t (m/s).
// Policy: friction changes only at converged evaluations.
Proposal evaluate_active(const ContactRows& rows, const ContactState& s, const Eigen::Vector3d& w,
                         const Eigen::Vector3d& f, double slack, const Eigen::Vector2d& u, const Evaluation& e) {
  Proposal p = unchanged(s, f);
  const double pull = -f[0] * w[0];  // m/s: how hard lambda pulls (positive) or pushes
  if (slack >= -e.eps2 && pull > e.eps2) {  // lines 5-6: separating and pulling
    switch_off(p);
    return p;
  }
  const double w_t = std::max(w[1], w[2]);
  if (s.mode == ContactMode::sticking) {  // lines 10-13
    if (e.converged) update_static_friction(rows, u, e, w_t, p);
    return p;
  }
  if (!e.converged) return p;  // u is not yet trustworthy
  if (reverses(rows, s, u, e, p)) return p;  // lines 14-16
  if (s.impending && u.norm() > e.eps2) {  // its slip has started: kinetic friction from now on
    p.state.impending = false;
    p.mode_change = p.accept = true;
    return p;
  }
  // Line 17: a directed slip moves with every other one (update_kinetic_friction).
  if (sliding_mu(rows, s) > 0.0 && s.slip.squaredNorm() == 0.0) direct_slip(rows, u, w_t, e, p);
  return p;
}

// The proposal index per contact (-1: none), for the exchange below.
std::vector<int> proposal_index(size_t contacts, const std::vector<Proposal>& proposals) {
  std::vector<int> index(contacts, -1);
  for (size_t i = 0; i < proposals.size(); ++i) index[static_cast<size_t>(proposals[i].contact)] = static_cast<int>(i);
  return index;
}

// How far, delta (N s), on-row contact t's multipliers f can move along
// the null-space direction -c delta (c: the coefficients of its normal and
// tangent rows in row_k = sum c_t row_t) before they reach a bound of its
// law: lambda = 0 (c_n > 0), or a sticking contact's gamma leaving its
// static cone, |gamma - c_t delta| = mu_s (lambda - c_n delta) with the
// difference growing; infinity when neither is reached. Where gamma and
// lambda vanish together the cone has closed to its tip: lambda = 0.
double room_along(const ContactRows& rows, const ContactState& s, const Eigen::Vector3d& f, const Eigen::Vector3d& c,
                  bool& reaches_cone) {
  const double lambda = std::max(f[0], 0.0);
  const double to_zero = c[0] > 0.0 ? lambda / c[0] : std::numeric_limits<double>::infinity();
  reaches_cone = false;
  if (s.mode != ContactMode::sticking) return to_zero;
  const Eigen::Vector2d gamma = f.tail<2>(), ct = c.tail<2>();
  if (std::isfinite(to_zero) && (gamma - ct * to_zero).norm() <= 4.0 * std::numeric_limits<double>::epsilon() *
                                                                     (gamma.norm() + ct.norm() * to_zero))
    return to_zero;
  const double mu = rows.mu_static;
  // g(d) = |gamma - ct d|^2 - mu^2 (lambda - c_n d)^2 = a d^2 + b d + e: the
  // first d >= 0 where g reaches 0 rising, g'(d) = 2 a d + b > 0. Of g's two
  // roots that is (-b + sqrt(disc)) / (2 a), computed without cancellation.
  const double a = ct.squaredNorm() - mu * mu * c[0] * c[0];
  const double b = -2.0 * gamma.dot(ct) + 2.0 * mu * mu * lambda * c[0];
  const double e = gamma.squaredNorm() - mu * mu * lambda * lambda;
  const double disc = b * b - 4.0 * a * e;
  double rim = std::numeric_limits<double>::infinity();
  if (e >= 0.0 && b > 0.0) {
    rim = 0.0;  // on or past the rim, and moving out
  } else if (a == 0.0) {
    if (b > 0.0) rim = std::max(-e / b, 0.0);
  } else if (disc > 0.0) {
    const double root = std::sqrt(disc);
    const double exit = b <= 0.0 ? (-b + root) / (2.0 * a) : 2.0 * e / (-b - root);
    if (exit >= 0.0) rim = exit;
  }
  if (rim > to_zero) return to_zero;
  reaches_cone = true;
  return rim;
}

// Activation k's normal row depends on on rows t (row_k = sum c_t row_t)
// and stays violated with all of them at equality: one of them makes way.
// The multipliers move along the null-space direction (+delta on k, -c_t
// delta on each t), which changes no impulse, until the first contact's
// reach a bound of its law (room_along; the ratio test of a dual
// active-set method): at lambda = 0 it switches off, its friction with it;
// at its static cone's rim it slides, opposing the friction it then
// applies. Returns false, and k waits, when a contact switched on by this
// evaluation takes part with c_n > 0 (it is deeper, and keeps its place)
// or no bound is reached (the rows together admit no dv at all, as for a
// body pinched from both sides).
bool exchange(const ContactProblem& problem, const RowDependence& d, int k, Eigen::VectorXd& y, int n,
              std::vector<Proposal>& proposals, std::vector<int>& index, OnRows& on) {
  // A contact this evaluation changes is read as the change leaves it.
  const auto proposal_of = [&](int t) -> Proposal* {
    const int p = index[static_cast<size_t>(t)];
    return p >= 0 && proposals[static_cast<size_t>(p)].accept ? &proposals[static_cast<size_t>(p)] : nullptr;
  };
  const auto multipliers = [&](int t) -> Eigen::Vector3d {
    const Proposal* p = proposal_of(t);
    return p ? p->f : Eigen::Vector3d(y.segment<3>(n + 3 * t));
  };
  int leaving = -1;
  bool slides = false;
  double delta = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < d.contacts.size(); ++i) {
    const int t = d.contacts[i];
    const Eigen::Vector3d& c = d.coefficients[i];
    const ContactState& now = problem.states[static_cast<size_t>(t)];
    if (now.mode == ContactMode::inactive && c[0] > 0.0) return false;
    const Proposal* p = proposal_of(t);
    bool reaches_cone = false;
    const double room = room_along(problem.rows[static_cast<size_t>(t)], p ? p->state : now, multipliers(t), c,
                                   reaches_cone);
    if (room < delta) {
      delta = room;
      leaving = t;
      slides = reaches_cone;
    }
  }
  if (leaving < 0) return false;
  for (size_t i = 0; i < d.contacts.size(); ++i) {
    const int t = d.contacts[i];
    const Eigen::Vector3d f = multipliers(t) - d.coefficients[i] * delta;
    y.segment<3>(n + 3 * t) = f;
    if (Proposal* p = proposal_of(t)) p->f = f;
  }
  y[n + 3 * k] += delta;
  proposals[static_cast<size_t>(index[static_cast<size_t>(k)])].f[0] = y[n + 3 * k];
  if (index[static_cast<size_t>(leaving)] < 0) {
    index[static_cast<size_t>(leaving)] = static_cast<int>(proposals.size());
    proposals.push_back(unchanged(problem.states[static_cast<size_t>(leaving)], y.segment<3>(n + 3 * leaving)));
    proposals.back().contact = leaving;
  }
  Proposal& p = proposals[static_cast<size_t>(index[static_cast<size_t>(leaving)])];
  if (slides) {
    break_away(problem.rows[static_cast<size_t>(leaving)], p);
    y.segment<2>(n + 3 * leaving + 1).setZero();
    on.add(leaving, false);
  } else {
    switch_off(p);
    y.segment<3>(n + 3 * leaving).setZero();
    on.remove(leaving);
  }
  return true;
}

// Policy (parallel) on the activations of one evaluation: the deepest goes
// first, and one whose normal row is within `parallel` of a row already
// taken waits. Mid-solve the active rows count as taken too; at a converged
// evaluation they do not, or a contact beside a loaded one could never come
// on. The rows that stay on (dependent_rows.h) are every active contact's
// normal row and a sticking one's tangent rows. A sliding contact whose
// tangent rows depend on them sticks only where their right-hand sides
// agree with its own to epsilon_2 (else its slip is theirs to decide, and it
// keeps sliding). An activation whose normal row depends on them comes on
// where they agree, or, at a converged evaluation, by exchange() where they
// leave it violated (mid-solve it waits: the ratio test on unconverged
// multipliers picked rows that the next evaluation swapped back); one they
// already satisfy waits. `proposals` holds the proposing contacts only, in
// ascending contact order but for the contacts an exchange changed, appended.
void hold_back(const ContactProblem& problem, const std::vector<Eigen::Vector3d>& inverse_masses,
               const MomentumPreconditioner& P, const Evaluation& e, Eigen::VectorXd& y, int n,
               std::vector<Proposal>& proposals) {
  std::vector<int> order;     // indices into `proposals`: the activations, deepest first
  std::vector<int> sticking;  // and the sliding contacts that stick
  for (size_t i = 0; i < proposals.size(); ++i) {
    const Proposal& p = proposals[i];
    const ContactMode now = problem.states[static_cast<size_t>(p.contact)].mode;
    if (!p.accept || !p.mode_change) continue;
    if (now == ContactMode::inactive) order.push_back(static_cast<int>(i));
    if (now == ContactMode::sliding && p.state.mode == ContactMode::sticking) sticking.push_back(static_cast<int>(i));
  }
  if (order.empty() && sticking.empty()) return;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return proposals[static_cast<size_t>(a)].depth > proposals[static_cast<size_t>(b)].depth;
  });
  TakenNormalRows taken(problem, inverse_masses, P, e.policy.parallel);
  if (!e.converged)
    for (size_t k = 0; k < problem.states.size(); ++k)
      if (problem.states[k].mode != ContactMode::inactive) taken.take(static_cast<int>(k));
  std::vector<int> index = proposal_index(problem.states.size(), proposals);
  OnRows on(problem, P);
  for (size_t k = 0; k < problem.states.size(); ++k) {
    if (problem.states[k].mode == ContactMode::inactive) continue;
    const int p = index[k];
    const ContactMode mode = p >= 0 && proposals[static_cast<size_t>(p)].accept
                                 ? proposals[static_cast<size_t>(p)].state.mode
                                 : problem.states[k].mode;
    if (mode != ContactMode::inactive) on.add(static_cast<int>(k), mode == ContactMode::sticking);
  }
  // Each contact about to stick is measured against all the others, so that
  // no order among them decides which one sticks.
  std::vector<int> rejected;
  for (int i : sticking) {
    const int k = proposals[static_cast<size_t>(i)].contact;
    for (int row = 1; row <= 2; ++row) {
      const RowDependence d = on.dependence(k, row);
      if (d.dependent && std::abs(d.mismatch) > e.eps2) {
        rejected.push_back(i);
        break;
      }
    }
  }
  for (int i : rejected) {
    proposals[static_cast<size_t>(i)].accept = false;
    on.add(proposals[static_cast<size_t>(i)].contact, false);
  }
  for (int i : order) {
    const int k = proposals[static_cast<size_t>(i)].contact;
    bool waits = taken.parallel_to_taken(k);
    // Where the on rows depend on each other too, one exchange can leave k
    // in the span of the rest: each exchange removes rows, so this ends.
    while (!waits) {
      const RowDependence d = on.dependence(k);
      if (!d.dependent || std::abs(d.mismatch) <= e.eps2) break;
      waits = d.mismatch < 0.0 || !e.converged || !exchange(problem, d, k, y, n, proposals, index, on);
    }
    if (waits) {
      proposals[static_cast<size_t>(i)].accept = false;
      y[n + 3 * k] = 0.0;  // what an exchange before a later wait gave it
    } else {
      taken.take(k);
      on.add(k, false);
    }
  }
}

// Algorithm 3 (UpdateKineticFriction) at a converged evaluation, for every
// sliding contact with a slip direction at once, the ones changing mode now
// (`changing`, ascending) aside: x = (lambda', slip angle) per contact moves
// toward G(x) = (lambda, the aim's angle), the aim being the slip this
// contact would have without its own friction, u + w_t mu lambda' slip (the
// fixed point itself for an isolated contact), through `acceleration`
// (lines 4-8). All move while one's G(x) - x, weighed as a velocity, is
// above epsilon_2 (line 18): to first order the KKT residual's friction
// error, and the step itself, so a contact the step cannot move (its slip
// reversed) never keeps the solve restarting; line 9's impulse
// -mu lambda' slip is what the states then hold.
// `tangential` holds u per contact, as Algorithm 2 read it for the active ones.
void update_kinetic_friction(const ContactProblem& problem, const std::vector<Eigen::Vector3d>& inverse_masses,
                             const Eigen::VectorXd& y, int n, const std::vector<Eigen::Vector2d>& tangential,
                             const std::vector<int>& changing, const Evaluation& e, FrictionAcceleration& acceleration,
                             std::vector<Proposal>& proposals) {
  std::vector<int> members;
  std::vector<double> x, g, weights;
  double worst = 0.0;  // m/s: the largest weighed entry of G(x) - x
  for (size_t k = 0; k < problem.states.size(); ++k) {
    const ContactState& s = problem.states[k];
    const ContactRows& rows = problem.rows[k];
    const double mu = sliding_mu(rows, s);
    if (s.mode != ContactMode::sliding || s.slip.squaredNorm() == 0.0 || mu <= 0.0 ||
        rows.nodes.empty() || std::binary_search(changing.begin(), changing.end(), static_cast<int>(k)))
      continue;
    const double w_t = std::max(inverse_masses[k][1], inverse_masses[k][2]);
    const Eigen::Vector2d& u = tangential[k];
    const Eigen::Vector2d target = u + w_t * mu * s.lambda_kinetic * s.slip;
    const Eigen::Vector2d aim = target.squaredNorm() > 0.0 ? target : s.slip;
    const double lambda = std::max(y[n + 3 * static_cast<Eigen::Index>(k)], 0.0);
    members.push_back(static_cast<int>(k));
    x.insert(x.end(), {s.lambda_kinetic, std::atan2(s.slip.y(), s.slip.x())});
    g.insert(g.end(), {lambda, std::atan2(aim.y(), aim.x())});
    weights.insert(weights.end(), {mu * w_t, mu * w_t * s.lambda_kinetic});
    const double turn = std::remainder(g.back() - x.back(), 2.0 * std::numbers::pi);
    worst = std::max({worst, weights[weights.size() - 2] * std::abs(lambda - s.lambda_kinetic),
                      weights.back() * std::abs(turn)});
  }
  if (members.empty() || !(worst > e.eps2)) return;
  const auto as_vector = [](const std::vector<double>& v) {
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
  };
  const Eigen::VectorXd next =
      acceleration.next(members, as_vector(x), as_vector(g), as_vector(weights), e.policy.friction_mixing);
  for (size_t i = 0; i < members.size(); ++i) {
    const int k = members[i];
    Proposal p = unchanged(problem.states[static_cast<size_t>(k)], y.segment<3>(n + 3 * k));
    p.contact = k;
    p.state.lambda_kinetic = std::max(next[static_cast<Eigen::Index>(2 * i)], 0.0);
    const double angle = next[static_cast<Eigen::Index>(2 * i + 1)];
    p.state.slip = Eigen::Vector2d(std::cos(angle), std::sin(angle));
    p.accept = true;
    proposals.push_back(p);
  }
}

}  // namespace

// Algorithm 2 (EvaluateConstraints): every contact's proposal (lines 3-17),
// the policy's hold-back, then the accepted changes applied (lines 18-21);
// the solver rebuilds the right-hand side (line 22).
EvaluationChanges evaluate_constraints(ContactProblem& problem, const std::vector<Eigen::Vector3d>& inverse_masses,
                                       Eigen::VectorXd& y, const MomentumPreconditioner& P,
                                       const ContactSolverSettings& settings, bool converged,
                                       FrictionAcceleration* acceleration) {
  const int m = static_cast<int>(problem.rows.size());
  const int n = static_cast<int>(y.size()) - 3 * m;
  RECOIL_CHECK(n >= 0 && static_cast<int>(inverse_masses.size()) == m && static_cast<int>(problem.states.size()) == m);
  const Evaluation e{settings.policy, settings.constraint_tolerance, converged};
  const Eigen::VectorXd dv = y.head(n);
  std::vector<Proposal> proposals;  // the contacts that propose a change: per-contact ones in ascending order, then
                                    // contacts an exchange changed, then Algorithm 3's
  std::vector<Eigen::Vector2d> tangential(static_cast<size_t>(m), Eigen::Vector2d::Zero());  // u of the active contacts, m/s
  for (int k = 0; k < m; ++k) {
    const ContactRows& rows = problem.rows[static_cast<size_t>(k)];
    const ContactState& s = problem.states[static_cast<size_t>(k)];
    const Eigen::Vector3d f = y.segment<3>(n + 3 * k);
    if (rows.nodes.empty()) continue;  // touches only fixed DoF: nothing to solve for
    Proposal p;
    if (s.mode == ContactMode::inactive) {
      // Most candidates are inactive and stay so: their normal row decides,
      // and the tangent rows are read only for one that comes on.
      const double slack = normal_row_times(rows, dv) - rows.rhs_normal;
      if (!(slack < -e.eps2)) continue;  // not penetrating (a NaN slack included)
      p = activate(rows, s, f, slack, rows_times(rows, dv).tail<2>() - rows.rhs_tangent, e);
    } else {
      const Eigen::Vector3d jdv = rows_times(rows, dv);
      const double slack = jdv[0] - rows.rhs_normal;
      const Eigen::Vector2d u = jdv.tail<2>() - rows.rhs_tangent;
      tangential[static_cast<size_t>(k)] = u;
      p = evaluate_active(rows, s, inverse_masses[static_cast<size_t>(k)], f, slack, u, e);
    }
    p.contact = k;
    if (p.accept) proposals.push_back(p);
  }
  hold_back(problem, inverse_masses, P, e, y, n, proposals);
  if (converged) {
    std::optional<FrictionAcceleration> fresh;  // for an evaluation that keeps no pairs
    if (acceleration == nullptr) acceleration = &fresh.emplace();
    std::vector<int> changing;
    for (const Proposal& p : proposals)
      if (p.accept && p.mode_change) changing.push_back(p.contact);
    std::sort(changing.begin(), changing.end());  // an exchange appends the contacts it changed
    // A change of modes changes the system that G(x) solved: the remembered pairs no longer hold.
    if (!changing.empty()) acceleration->reset();
    update_kinetic_friction(problem, inverse_masses, y, n, tangential, changing, e, *acceleration, proposals);
  }
  EvaluationChanges changed;
  for (const Proposal& p : proposals) {
    if (!p.accept) continue;
    const int k = p.contact;
    problem.states[static_cast<size_t>(k)] = p.state;
    y.segment<3>(n + 3 * k) = p.f;
    if (p.mode_change) {
      ++changed.mode_changes;
    } else {
      ++changed.friction_updates;
    }
  }
  return changed;
}

}  // namespace recoil::sim
