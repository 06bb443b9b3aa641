#include "sim/solver/dependent_rows.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "sim/solver/contact_rows_ops.h"

namespace recoil::sim {

namespace {

// Rounding, as a share: of sin^2 of the angle between a row and the span of
// others (rows assembled from unit normals and lever arms leave about 1e-15
// where they depend exactly), of the largest squared pivot of the on rows'
// decomposition (their own dependencies among themselves, a box face's
// fourth corner), and of the largest coefficient. Rows merely close to each
// other's span are not dependent here: docs/decisions/023-dependent-rows-exchange.md.
constexpr double kRounding = 1e-10;

}  // namespace

OnRows::OnRows(const ContactProblem& problem, const MomentumPreconditioner& P)
    : m_problem(problem), m_P(P), m_on(problem.rows.size(), Off), m_whitened(problem.rows.size()),
      m_seen(problem.rows.size(), 0) {}

double OnRows::right_hand_side(int k, int row) const {
  const ContactRows& rows = m_problem.rows[static_cast<size_t>(k)];
  return row == 0 ? rows.rhs_normal : rows.rhs_tangent[row - 1];
}

void OnRows::add(int k, bool sticking) {
  Mode& on = m_on[static_cast<size_t>(k)];
  const bool indexed = on != Off;
  on = sticking ? NormalAndTangents : Normal;
  if (indexed) return;
  for (int node : m_problem.rows[static_cast<size_t>(k)].nodes) {
    std::vector<int>& bucket = m_by_node[node];
    if (std::find(bucket.begin(), bucket.end(), k) == bucket.end()) bucket.push_back(k);
  }
}

void OnRows::remove(int k) { m_on[static_cast<size_t>(k)] = Off; }

const OnRows::WhitenedRows& OnRows::whitened(int k) {
  std::optional<WhitenedRows>& out = m_whitened[static_cast<size_t>(k)];
  if (out) return *out;
  const ContactRows& rows = m_problem.rows[static_cast<size_t>(k)];
  out.emplace();
  out->nodes = rows.nodes;
  for (size_t i = 0; i < rows.nodes.size(); ++i) {
    const Eigen::LLT<Eigen::Matrix3d> llt(m_P.diagonal_inverse(rows.nodes[i]));
    out->blocks.push_back(rows.blocks[i] * llt.matrixL().toDenseMatrix());
  }
  const ContactRowModes modes = contact_row_modes(rows, m_P);
  for (size_t slot = 0; slot < static_cast<size_t>(modes.count); ++slot) {
    const int body = modes.body[slot];
    const Eigen::LLT<MomentumPreconditioner::CoarseMatrix> llt(m_P.coarse_inverse(body));
    out->bodies.push_back(body);
    out->modes.push_back(modes.rows_times_modes[slot] * llt.matrixL().toDenseMatrix());
  }
  return *out;
}

RowDependence OnRows::dependence(int k, int row) {
  RowDependence out;
  ++m_query;
  std::vector<int> contacts;
  for (int node : m_problem.rows[static_cast<size_t>(k)].nodes) {
    const auto bucket = m_by_node.find(node);
    if (bucket == m_by_node.end()) continue;
    for (int t : bucket->second) {
      int& seen = m_seen[static_cast<size_t>(t)];
      if (seen == m_query || !on(t)) continue;
      seen = m_query;
      contacts.push_back(t);
    }
  }
  // The on rows of those contacts, as (contact, row), grouped by contact.
  std::vector<std::pair<int, int>> rows;
  for (int t : contacts)
    for (int r = 0; r < (m_on[static_cast<size_t>(t)] == NormalAndTangents ? 3 : 1); ++r)
      if (t != k || r < row) rows.emplace_back(t, r);
  if (rows.empty()) return out;
  // Columns: 3 per DoF node the rows touch, 6 per deformable body's rigid motions.
  std::unordered_map<int, Eigen::Index> node_column, body_column;
  Eigen::Index columns = 0;
  const auto assign = [&](const WhitenedRows& w) {
    for (int node : w.nodes)
      if (node_column.emplace(node, columns).second) columns += 3;
    for (int body : w.bodies)
      if (body_column.emplace(body, columns).second) columns += 6;
  };
  for (int t : contacts) assign(whitened(t));
  assign(whitened(k));
  const auto fill = [&](const WhitenedRows& w, int row, Eigen::Ref<Eigen::VectorXd> column) {
    for (size_t i = 0; i < w.nodes.size(); ++i)
      column.segment<3>(node_column[w.nodes[i]]) = w.blocks[i].row(row).transpose();
    for (size_t b = 0; b < w.bodies.size(); ++b)
      column.segment<6>(body_column[w.bodies[b]]) = w.modes[b].row(row).transpose();
  };
  const Eigen::Index m = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd on_rows = Eigen::MatrixXd::Zero(columns, m);  // the on rows as columns, whitened
  for (Eigen::Index i = 0; i < m; ++i) fill(whitened(rows[size_t(i)].first), rows[size_t(i)].second, on_rows.col(i));
  Eigen::VectorXd row_k = Eigen::VectorXd::Zero(columns);
  fill(whitened(k), row, row_k);
  const double own = row_k.squaredNorm();
  if (!(own > 0.0)) return out;
  // Least-squares coefficients of least norm: the on rows may depend on each other too.
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition(on_rows.rows(), on_rows.cols());
  decomposition.setThreshold(std::sqrt(kRounding));
  decomposition.compute(on_rows);
  const Eigen::VectorXd c = decomposition.solve(row_k);
  const double residual = (row_k - on_rows * c).squaredNorm();
  out.dependent = residual <= kRounding * own;
  if (!out.dependent) return out;
  const double largest = c.cwiseAbs().maxCoeff();
  out.mismatch = right_hand_side(k, row);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto [t, r] = rows[size_t(i)];
    if (out.contacts.empty() || out.contacts.back() != t) {
      out.contacts.push_back(t);
      out.coefficients.push_back(Eigen::Vector3d::Zero());
    }
    const double coefficient = std::abs(c[i]) > kRounding * largest ? c[i] : 0.0;
    out.coefficients.back()[r] = coefficient;
    out.mismatch -= coefficient * right_hand_side(t, r);
  }
  return out;
}

}  // namespace recoil::sim
