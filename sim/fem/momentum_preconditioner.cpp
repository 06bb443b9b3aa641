#include "sim/fem/momentum_preconditioner.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/check.h"
#include "sim/geometry/skew.h"

namespace recoil::sim {

namespace {

// Directions of Z^T Z (dimensionless, 6x6; its translation block is #nodes
// times I) below this share of #nodes are left out of the coarse space: a
// body whose free nodes are collinear, or a single node, has no rotation
// about that line, and Z^T A Z is singular there however stiff A is.
constexpr double kDegenerateMode = 1e-10;

// The inverse of S = Z^T A Z on the span of the body's rigid motions, the
// directions of G = Z^T Z that are not degenerate: V (V^T S V)^-1 V^T. The
// rank comes from the geometry alone, never from S, whose eigenvalues range
// from the body's mass (free motions) to h^2 k (motions a pin holds).
MomentumPreconditioner::CoarseMatrix coarse_inverse_on_span(const MomentumPreconditioner::CoarseMatrix& S,
                                                            const MomentumPreconditioner::CoarseMatrix& G,
                                                            double nodes) {
  const Eigen::SelfAdjointEigenSolver<MomentumPreconditioner::CoarseMatrix> eig(G);
  int rank = 0;
  Eigen::Matrix<double, 6, 6> V = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < 6; ++i)
    if (eig.eigenvalues()[i] > kDegenerateMode * nodes) V.col(rank++) = eig.eigenvectors().col(i);
  const Eigen::MatrixXd basis = V.leftCols(rank);
  const Eigen::MatrixXd reduced = basis.transpose() * S * basis;
  // S is SPD on that span for SPD A; a rounding that says otherwise (a
  // condition number near 1e16) leaves the body to the block diagonal alone.
  const Eigen::LLT<Eigen::MatrixXd> llt(reduced);
  if (llt.info() != Eigen::Success) return MomentumPreconditioner::CoarseMatrix::Zero();
  return basis * llt.solve(basis.transpose());
}

}  // namespace

MomentumPreconditioner::MomentumPreconditioner(const BlockSparseMatrix& A, const std::vector<RigidModeNodes>& bodies) {
  const int n = A.block_rows();
  m_inv_diag.resize(static_cast<size_t>(n));
  bool all_spd = true;
  for (int r = 0; r < n; ++r) {
    // A block that is not SPD comes only from a state gone non-finite, which
    // the step's health check reports: identity lets that step finish.
    const Eigen::LLT<Eigen::Matrix3d> llt(A.diagonal_block(r));
    const bool spd = llt.info() == Eigen::Success;
    all_spd = all_spd && spd;
    m_inv_diag[static_cast<size_t>(r)] =
        spd ? Eigen::Matrix3d(llt.solve(Eigen::Matrix3d::Identity())) : Eigen::Matrix3d(Eigen::Matrix3d::Identity());
  }
  if (bodies.empty() || !all_spd) return;

  // Arms from each body's centroid, divided by the body's RMS arm so that
  // both halves of Z are dimensionless and Z^T A Z is in kg throughout.
  m_body_of_node.assign(static_cast<size_t>(n), -1);
  m_arm.assign(static_cast<size_t>(n), Eigen::Vector3d::Zero());
  for (size_t b = 0; b < bodies.size(); ++b) {
    const RigidModeNodes& body = bodies[b];
    RECOIL_CHECK(body.nodes.size() == body.positions.size(), "one position per rigid-mode node");
    m_body_nodes.push_back(body.nodes);
    if (body.nodes.empty()) continue;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& x : body.positions) centroid += x;
    centroid /= static_cast<double>(body.positions.size());
    double square_sum = 0.0;
    for (const Eigen::Vector3d& x : body.positions) square_sum += (x - centroid).squaredNorm();
    const double scale = std::sqrt(square_sum / static_cast<double>(body.positions.size()));
    for (size_t i = 0; i < body.nodes.size(); ++i) {
      const int node = body.nodes[i];
      RECOIL_CHECK(node >= 0 && node < n && m_body_of_node[static_cast<size_t>(node)] < 0,
                   "rigid-mode node " << node << " out of range or in two bodies");
      m_body_of_node[static_cast<size_t>(node)] = static_cast<int>(b);
      m_arm[static_cast<size_t>(node)] = scale > 0.0 ? Eigen::Vector3d((body.positions[i] - centroid) / scale) : Eigen::Vector3d::Zero();
    }
  }

  // Z^T A Z for every body at once from six products with A: column j of
  // every body's Z stacked into one vector (A couples no two bodies).
  std::vector<CoarseMatrix> coarse(bodies.size(), CoarseMatrix::Zero()), gram(bodies.size(), CoarseMatrix::Zero());
  for (int node = 0; node < n; ++node) {
    const int b = m_body_of_node[static_cast<size_t>(node)];
    if (b >= 0) gram[static_cast<size_t>(b)] += mode_block(node).transpose() * mode_block(node);
  }
  Eigen::VectorXd column(A.rows()), product;
  for (int j = 0; j < 6; ++j) {
    column.setZero();
    for (int node = 0; node < n; ++node)
      if (m_body_of_node[static_cast<size_t>(node)] >= 0) column.segment<3>(3 * node) = mode_block(node).col(j);
    A.multiply(column, product);
    for (int node = 0; node < n; ++node) {
      const int b = m_body_of_node[static_cast<size_t>(node)];
      if (b >= 0) coarse[static_cast<size_t>(b)].col(j) += mode_block(node).transpose() * product.segment<3>(3 * node);
    }
  }
  m_coarse_inverse.reserve(coarse.size());
  for (size_t b = 0; b < coarse.size(); ++b) {
    const CoarseMatrix symmetric = 0.5 * (coarse[b] + coarse[b].transpose());
    m_coarse_inverse.push_back(
        coarse_inverse_on_span(symmetric, gram[b], static_cast<double>(bodies[b].nodes.size())));
  }
}

MomentumPreconditioner::ModeBlock MomentumPreconditioner::mode_block(int node) const {
  ModeBlock Z;
  Z.leftCols<3>().setIdentity();
  Z.rightCols<3>() = -skew(m_arm[static_cast<size_t>(node)]);
  return Z;
}

std::vector<MomentumPreconditioner::CoarseVector> MomentumPreconditioner::coarse_solution(const Vector& x) const {
  // Z^T x = (sum x_i, sum arm_i x x_i) per body, then S^-1 of it.
  std::vector<CoarseVector> c(m_coarse_inverse.size());
  for (size_t b = 0; b < c.size(); ++b) {
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
    for (int node : m_body_nodes[b]) {
      const Eigen::Vector3d xi = x.segment<3>(3 * node);
      force += xi;
      torque += m_arm[static_cast<size_t>(node)].cross(xi);
    }
    CoarseVector moment;
    moment << force, torque;
    c[b] = m_coarse_inverse[b] * moment;
  }
  return c;
}

void MomentumPreconditioner::apply(const Vector& x, Eigen::Ref<Eigen::VectorXd> out) const {
  const int n = static_cast<int>(m_inv_diag.size());
  RECOIL_CHECK(x.size() == 3 * n && out.size() == x.size(), "P_A^-1 applied to a vector of the wrong size");
  for (int node = 0; node < n; ++node) out.segment<3>(3 * node) = m_inv_diag[static_cast<size_t>(node)] * x.segment<3>(3 * node);
  const std::vector<CoarseVector> c = coarse_solution(x);
  for (size_t b = 0; b < c.size(); ++b)
    for (int node : m_body_nodes[b]) out.segment<3>(3 * node) += motion_at(c[b], node);
}

double MomentumPreconditioner::applied_squared_norm(const Vector& x, double stop_above) const {
  const int n = static_cast<int>(m_inv_diag.size());
  RECOIL_CHECK(x.size() == 3 * n, "P_A^-1 applied to a vector of the wrong size");
  const std::vector<CoarseVector> c = coarse_solution(x);
  double sum = 0.0;
  for (int node = 0; node < n; ++node) {
    Eigen::Vector3d v = m_inv_diag[static_cast<size_t>(node)] * x.segment<3>(3 * node);
    const int b = body_of(node);
    if (b >= 0) v += motion_at(c[static_cast<size_t>(b)], node);
    sum += v.squaredNorm();
    if (sum > stop_above) return sum;
  }
  return sum;
}

}  // namespace recoil::sim
