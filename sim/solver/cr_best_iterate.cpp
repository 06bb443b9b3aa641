#include "sim/solver/cr_best_iterate.h"

#include <utility>

#include "sim/solver/cr_hand_back.h"
#include "sim/solver/kkt_residual.h"

namespace recoil::sim {

double BestIterate::kkt_of(const Eigen::VectorXd& y, const std::vector<ContactState>& states) {
  std::vector<ContactState> filled(m_problem.rows.size());
  for (size_t k = 0; k < states.size(); ++k) {
    filled[k] = states[k];
    if (filled[k].mode != ContactMode::inactive) take_multipliers(y, m_n, static_cast<int>(k), filled[k]);
  }
  // `states` is read before the swap, so it may be m_problem.states.
  std::swap(filled, m_problem.states);
  const double kkt = kkt_residual(m_problem, y.head(m_n), m_P).max();
  std::swap(filled, m_problem.states);
  return kkt;
}

double BestIterate::offer(const Eigen::VectorXd& y) {
  const double kkt = kkt_of(y, m_problem.states);
  if (kkt >= m_kkt) return kkt;
  m_kkt = kkt;
  m_y = y;
  m_states = m_problem.states;
  return kkt;
}

void BestIterate::remeasure() {
  if (m_y.size() > 0) m_kkt = kkt_of(m_y, m_states);
}

bool BestIterate::restore_if_better(Eigen::VectorXd& y) {
  if (m_y.size() == 0) return false;
  if (kkt_of(y, m_problem.states) <= m_kkt) return false;
  y.setZero();
  y.head(m_y.size()) = m_y;
  m_problem.states = m_states;
  m_problem.states.resize(m_problem.rows.size());  // contacts added since: inactive (default)
  return true;
}

}  // namespace recoil::sim
