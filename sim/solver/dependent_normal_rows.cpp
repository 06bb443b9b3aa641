#include "sim/solver/dependent_normal_rows.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace recoil::sim {

namespace {

// Rounding, as a share: of sin^2 of the angle between a row and the span of
// others (rows assembled from unit normals and lever arms leave about 1e-15
// where they depend exactly), of the Gram matrix's largest eigenvalue (the
// on rows' own dependencies among themselves, a box face's fourth corner),
// and of the largest coefficient. Rows merely close to each other's span
// are not dependent here: docs/decisions/023-dependent-rows-exchange.md.
constexpr double kRounding = 1e-10;

}  // namespace

OnNormalRows::OnNormalRows(const ContactProblem& problem, const MomentumPreconditioner& P)
    : m_problem(problem), m_P(P), m_on(problem.rows.size(), 0), m_modes(problem.rows.size()),
      m_seen(problem.rows.size(), 0) {}

const NormalRowModes& OnNormalRows::modes(int k) {
  std::optional<NormalRowModes>& modes = m_modes[static_cast<size_t>(k)];
  if (!modes) modes = normal_row_modes(m_problem.rows[static_cast<size_t>(k)], m_P);
  return *modes;
}

void OnNormalRows::add(int k) {
  char& on = m_on[static_cast<size_t>(k)];
  if (on) return;
  on = 1;
  for (int node : m_problem.rows[static_cast<size_t>(k)].nodes) {
    std::vector<int>& bucket = m_by_node[node];
    if (std::find(bucket.begin(), bucket.end(), k) == bucket.end()) bucket.push_back(k);
  }
}

void OnNormalRows::remove(int k) { m_on[static_cast<size_t>(k)] = 0; }

NormalRowDependence OnNormalRows::dependence(int k) {
  NormalRowDependence out;
  ++m_query;
  m_seen[static_cast<size_t>(k)] = m_query;
  std::vector<int>& rows = out.contacts;
  for (int node : m_problem.rows[static_cast<size_t>(k)].nodes) {
    const auto bucket = m_by_node.find(node);
    if (bucket == m_by_node.end()) continue;
    for (int t : bucket->second) {
      int& seen = m_seen[static_cast<size_t>(t)];
      if (seen == m_query || !on(t)) continue;
      seen = m_query;
      rows.push_back(t);
    }
  }
  if (rows.empty()) return out;
  const auto product = [&](int a, int b) {
    return normal_rows_product(m_problem.rows[static_cast<size_t>(a)], modes(a), m_problem.rows[static_cast<size_t>(b)],
                               modes(b), m_P);
  };
  const Eigen::Index m = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd gram(m, m);  // P_A^-1 products of the on rows, (1/kg)
  Eigen::VectorXd with_k(m);   // their products with row k
  for (Eigen::Index i = 0; i < m; ++i) {
    for (Eigen::Index j = 0; j <= i; ++j) gram(i, j) = gram(j, i) = product(rows[size_t(i)], rows[size_t(j)]);
    with_k[i] = product(rows[size_t(i)], k);
  }
  const double own = product(k, k);
  if (!(own > 0.0)) {
    rows.clear();
    return out;
  }
  // Least-squares coefficients through the pseudo-inverse: the on rows may
  // depend on each other too.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  const Eigen::VectorXd& values = eigen.eigenvalues();
  const Eigen::VectorXd along = eigen.eigenvectors().transpose() * with_k;
  Eigen::VectorXd scaled = Eigen::VectorXd::Zero(m);
  for (Eigen::Index i = 0; i < m; ++i)
    if (values[i] > kRounding * values.maxCoeff()) scaled[i] = along[i] / values[i];
  const Eigen::VectorXd c = eigen.eigenvectors() * scaled;
  const double residual = own - with_k.dot(c);
  out.dependent = residual <= kRounding * own;
  if (!out.dependent) {
    rows.clear();
    return out;
  }
  const double largest = c.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < m; ++i) out.coefficients.push_back(std::abs(c[i]) > kRounding * largest ? c[i] : 0.0);
  out.mismatch = m_problem.rows[static_cast<size_t>(k)].rhs_normal;
  for (Eigen::Index i = 0; i < m; ++i)
    out.mismatch -= out.coefficients[size_t(i)] * m_problem.rows[size_t(rows[size_t(i)])].rhs_normal;
  return out;
}

}  // namespace recoil::sim
