#include "sim/solver/constraint_evaluation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <Eigen/Geometry>

#include "core/check.h"
#include "sim/solver/contact_rows_ops.h"
#include "sim/solver/dependent_normal_rows.h"
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
  p.state.impending = rows.mu_static > rows.mu_kinetic;
  p.state.gamma.setZero();
  p.f.tail<2>().setZero();
  p.mode_change = p.accept = true;
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

// Activation k's normal row depends on on rows t (row_k = sum c_t row_t) and
// stays violated with all of them at equality: one of them makes way. The
// normal multipliers move along the null-space direction (+delta on k,
// -c_t delta on each t), which changes no normal impulse, until the first
// lambda_t with c_t > 0 (a negative one read as zero) reaches zero; that
// row switches off, its friction with it, and with every row but it at
// equality its slack is mismatch / c_t > 0 (the ratio test of a dual
// active-set method). Returns false, and k waits, when a row switched on by
// this evaluation takes part (c_t > 0: it is deeper, and keeps its place)
// or no row has c_t > 0 (the rows together admit no dv at all, as for a
// body pinched from both sides).
bool exchange(const ContactProblem& problem, const NormalRowDependence& d, int k, Eigen::VectorXd& y, int n,
              std::vector<Proposal>& proposals, std::vector<int>& index, OnNormalRows& on) {
  int leaving = -1;
  double delta = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < d.contacts.size(); ++i) {
    const int t = d.contacts[i];
    const double c = d.coefficients[i];
    if (!(c > 0.0)) continue;
    if (problem.states[static_cast<size_t>(t)].mode == ContactMode::inactive) return false;
    const double ratio = std::max(y[n + 3 * t], 0.0) / c;
    if (ratio < delta) {
      delta = ratio;
      leaving = t;
    }
  }
  if (leaving < 0) return false;
  const auto set_lambda = [&](int contact, double lambda) {
    y[n + 3 * contact] = lambda;
    const int p = index[static_cast<size_t>(contact)];
    if (p >= 0) proposals[static_cast<size_t>(p)].f[0] = lambda;
  };
  for (size_t i = 0; i < d.contacts.size(); ++i) {
    const int t = d.contacts[i];
    if (t != leaving) set_lambda(t, y[n + 3 * t] - d.coefficients[i] * delta);
  }
  set_lambda(k, delta);
  if (index[static_cast<size_t>(leaving)] < 0) {
    index[static_cast<size_t>(leaving)] = static_cast<int>(proposals.size());
    proposals.push_back(unchanged(problem.states[static_cast<size_t>(leaving)], y.segment<3>(n + 3 * leaving)));
    proposals.back().contact = leaving;
  }
  switch_off(proposals[static_cast<size_t>(index[static_cast<size_t>(leaving)])]);
  y.segment<3>(n + 3 * leaving).setZero();
  on.remove(leaving);
  return true;
}

// Policy (parallel) on the activations of one evaluation: the deepest goes
// first, and one whose normal row is within `parallel` of a row already
// taken waits. Mid-solve the active rows count as taken too; at a converged
// evaluation they do not, or a contact beside a loaded one could never come
// on. Then an activation whose row depends on the rows that stay on
// (dependent_normal_rows.h) comes on only where their right-hand sides
// agree with its own to epsilon_2, or, at a converged evaluation, by
// exchange() where they leave it violated (mid-solve it waits: the ratio
// test on unconverged multipliers picked rows that the next evaluation
// swapped back); one they already satisfy waits. `proposals` holds the proposing
// contacts only, in ascending contact order but for the rows an exchange
// switched off, appended.
void hold_back(const ContactProblem& problem, const std::vector<Eigen::Vector3d>& inverse_masses,
               const MomentumPreconditioner& P, const Evaluation& e, Eigen::VectorXd& y, int n,
               std::vector<Proposal>& proposals) {
  std::vector<int> order;  // indices into `proposals`: the activations, deepest first
  for (size_t i = 0; i < proposals.size(); ++i) {
    const Proposal& p = proposals[i];
    const bool active = problem.states[static_cast<size_t>(p.contact)].mode != ContactMode::inactive;
    if (!active && p.accept && p.mode_change) order.push_back(static_cast<int>(i));
  }
  if (order.empty()) return;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return proposals[static_cast<size_t>(a)].depth > proposals[static_cast<size_t>(b)].depth;
  });
  TakenNormalRows taken(problem, inverse_masses, P, e.policy.parallel);
  if (!e.converged)
    for (size_t k = 0; k < problem.states.size(); ++k)
      if (problem.states[k].mode != ContactMode::inactive) taken.take(static_cast<int>(k));
  std::vector<int> index = proposal_index(problem.states.size(), proposals);
  OnNormalRows on(problem, P);
  for (size_t k = 0; k < problem.states.size(); ++k) {
    if (problem.states[k].mode == ContactMode::inactive) continue;
    const int p = index[k];
    const bool leaves = p >= 0 && proposals[static_cast<size_t>(p)].accept &&
                        proposals[static_cast<size_t>(p)].state.mode == ContactMode::inactive;
    if (!leaves) on.add(static_cast<int>(k));
  }
  for (int i : order) {
    const int k = proposals[static_cast<size_t>(i)].contact;
    bool waits = taken.parallel_to_taken(k);
    if (!waits) {
      const NormalRowDependence d = on.dependence(k);
      if (d.dependent && std::abs(d.mismatch) > e.eps2)
        waits = d.mismatch < 0.0 || !e.converged || !exchange(problem, d, k, y, n, proposals, index, on);
    }
    if (waits) {
      proposals[static_cast<size_t>(i)].accept = false;
    } else {
      taken.take(k);
      on.add(k);
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
                                    // rows an exchange switched off, then Algorithm 3's
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
    std::sort(changing.begin(), changing.end());  // an exchange appends the row it switched off
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
