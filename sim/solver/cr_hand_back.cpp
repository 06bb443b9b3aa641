#include "sim/solver/cr_hand_back.h"

namespace recoil::sim {

void take_multipliers(const Eigen::VectorXd& y, int n, int k, ContactState& s) {
  s.lambda = y[n + 3 * k];
  s.gamma = s.mode == ContactMode::sticking ? Eigen::Vector2d(y.segment<2>(n + 3 * k + 1)) : Eigen::Vector2d::Zero();
}

void hand_back_states(ContactProblem& problem, const Eigen::VectorXd& y, ContactSolverStats& stats) {
  const int m = static_cast<int>(problem.rows.size());
  const int n = static_cast<int>(y.size()) - 3 * m;
  for (int k = 0; k < m; ++k) {
    ContactState& s = problem.states[static_cast<size_t>(k)];
    if (s.mode == ContactMode::inactive) {
      s = ContactState{};
      continue;
    }
    take_multipliers(y, n, k, s);
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
