#include "sim/solver/taken_normal_rows.h"

#include <cmath>

namespace recoil::sim {

TakenNormalRows::TakenNormalRows(const ContactProblem& problem, const std::vector<Eigen::Vector3d>& inverse_masses,
                                 const MomentumPreconditioner& P, double cosine)
    : m_problem(problem), m_inverse_masses(inverse_masses), m_P(P), m_cosine(cosine),
      m_modes(problem.rows.size()), m_measured(problem.rows.size(), 0) {}

const TakenNormalRows::Modes& TakenNormalRows::modes(int k) {
  Modes& out = m_modes[static_cast<size_t>(k)];
  if (out.share < 0.0) {
    out.modes = normal_row_modes(m_problem.rows[static_cast<size_t>(k)], m_P);
    const double w = m_inverse_masses[static_cast<size_t>(k)][0];
    out.share = w > 0.0 ? std::sqrt(normal_row_rigid_part(out.modes, m_P) / w) : 0.0;
  }
  return out;
}

bool TakenNormalRows::measure(int k, int t) {
  int& last = m_measured[static_cast<size_t>(t)];
  if (last == m_proposal) return false;
  last = m_proposal;
  const double w_k = m_inverse_masses[static_cast<size_t>(k)][0];
  const double w_t = m_inverse_masses[static_cast<size_t>(t)][0];
  if (!(w_k > 0.0 && w_t > 0.0)) return false;
  const double product = normal_rows_product(m_problem.rows[static_cast<size_t>(k)], modes(k).modes,
                                             m_problem.rows[static_cast<size_t>(t)], modes(t).modes, m_P);
  return product > m_cosine * std::sqrt(w_k * w_t);
}

bool TakenNormalRows::parallel_to_taken(int k) {
  ++m_proposal;
  const ContactRows& rows = m_problem.rows[static_cast<size_t>(k)];
  for (int node : rows.nodes) {
    const auto bucket = m_by_node.find(node);
    if (bucket == m_by_node.end()) continue;
    for (int t : bucket->second)
      if (measure(k, t)) return true;
  }
  const Modes& own = modes(k);
  if (!(own.share > m_cosine)) return false;
  for (int slot = 0; slot < own.modes.count; ++slot) {
    const auto bucket = m_by_body.find(own.modes.body[static_cast<size_t>(slot)]);
    if (bucket == m_by_body.end()) continue;
    for (int t : bucket->second)
      if (own.share * modes(t).share > m_cosine && measure(k, t)) return true;
  }
  return false;
}

void TakenNormalRows::take(int k) {
  const ContactRows& rows = m_problem.rows[static_cast<size_t>(k)];
  for (int node : rows.nodes) m_by_node[node].push_back(k);
  const Modes& own = modes(k);
  if (!(own.share > m_cosine)) return;
  for (int slot = 0; slot < own.modes.count; ++slot) m_by_body[own.modes.body[static_cast<size_t>(slot)]].push_back(k);
}

}  // namespace recoil::sim
