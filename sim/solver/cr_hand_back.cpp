#include "sim/solver/cr_hand_back.h"

#include <algorithm>

#include "sim/solver/contact_rows_ops.h"

namespace recoil::sim {

namespace {

// How far (m/s) an active contact's multipliers and velocity are from its
// mode's law: a pull, a sticking impulse outside the cone, a slip running
// backwards against the kinetic impulse.
double frozen_violation(const ContactRows& rows, const ContactState& s, const ContactTrack& track,
                        const Eigen::VectorXd& dv) {
  const double w_t = std::max(track.w[1], track.w[2]);
  double violation = -s.lambda * track.w[0];
  if (s.mode == ContactMode::sticking)
    violation = std::max(violation, (s.gamma.norm() - rows.mu_static * std::max(s.lambda, 0.0)) * w_t);
  if (s.mode == ContactMode::sliding) {
    const Eigen::Vector2d u = rows_times(rows, dv).tail<2>() - rows.rhs_tangent;
    violation = std::max(violation, -u.dot(s.slip));
  }
  return violation;
}

}  // namespace

void take_multipliers(const Eigen::VectorXd& y, int n, int k, ContactState& s) {
  s.lambda = y[n + 3 * k];
  s.gamma = s.mode == ContactMode::sticking ? Eigen::Vector2d(y.segment<2>(n + 3 * k + 1)) : Eigen::Vector2d::Zero();
}

void hand_back_states(ContactProblem& problem, const std::vector<ContactTrack>& tracks, const Eigen::VectorXd& y,
                      const ContactSolverSettings& settings, ContactSolverStats& stats) {
  const int m = static_cast<int>(problem.rows.size());
  const int n = static_cast<int>(y.size()) - 3 * m;
  const Eigen::VectorXd dv = y.head(n);
  for (int k = 0; k < m; ++k) {
    ContactState& s = problem.states[static_cast<size_t>(k)];
    const ContactTrack& track = tracks[static_cast<size_t>(k)];
    const ContactRows& rows = problem.rows[static_cast<size_t>(k)];
    if (s.mode == ContactMode::inactive) {
      s = ContactState{};
      if (track.locked_off && rows_times(rows, dv)[0] - rows.rhs_normal < -settings.constraint_tolerance)
        stats.converged = false;
      continue;
    }
    take_multipliers(y, n, k, s);
    // Frozen: stats.frozen counts the active ones, as contact_problem.h says.
    if (track.flips >= settings.max_flips) {
      ++stats.frozen;
      if (frozen_violation(rows, s, track, dv) > settings.constraint_tolerance) stats.converged = false;
    }
    // An impending contact holds at zero slip: it sticks at the cone's rim.
    if (s.mode == ContactMode::sticking || s.impending) {
      ++stats.sticking;
    } else {
      ++stats.sliding;
    }
    ++stats.active;
  }
}

}  // namespace recoil::sim
