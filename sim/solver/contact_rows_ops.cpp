#include "sim/solver/contact_rows_ops.h"

#include <Eigen/LU>
#include <algorithm>

#include "core/check.h"

namespace recoil::sim {

Eigen::Vector3d rows_times(const ContactRows& rows, const Eigen::VectorXd& dv) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < rows.nodes.size(); ++i) out.noalias() += rows.blocks[i] * dv.segment<3>(3 * rows.nodes[i]);
  return out;
}

void add_rows_transpose_times(const ContactRows& rows, const Eigen::Vector3d& f, Eigen::VectorXd& out) {
  for (size_t i = 0; i < rows.nodes.size(); ++i)
    out.segment<3>(3 * rows.nodes[i]).noalias() += rows.blocks[i].transpose() * f;
}

double normal_row_times(const ContactRows& rows, const Eigen::VectorXd& dv) {
  double out = 0.0;
  for (size_t i = 0; i < rows.nodes.size(); ++i) {
    const Eigen::Matrix3d& b = rows.blocks[i];
    const Eigen::Vector3d v = dv.segment<3>(3 * rows.nodes[i]);
    out += b(0, 0) * v[0] + b(0, 1) * v[1] + b(0, 2) * v[2];
  }
  return out;
}

void add_normal_row_transpose_times(const ContactRows& rows, double lambda, Eigen::VectorXd& out) {
  for (size_t i = 0; i < rows.nodes.size(); ++i)
    out.segment<3>(3 * rows.nodes[i]).noalias() += rows.blocks[i].row(0).transpose() * lambda;
}

std::vector<Eigen::Matrix3d> inverse_diagonal_blocks(const BlockSparseMatrix& A) {
  std::vector<Eigen::Matrix3d> out(static_cast<size_t>(A.block_rows()));
  for (int r = 0; r < A.block_rows(); ++r) {
    const Eigen::Matrix3d& block = A.diagonal_block(r);
    RECOIL_CHECK(block.determinant() > 0.0, "diagonal block " << r << " of A is not SPD");
    out[static_cast<size_t>(r)] = block.inverse();
  }
  return out;
}

Eigen::Vector3d effective_inverse_mass(const ContactRows& rows, const std::vector<Eigen::Matrix3d>& inv_diag) {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < rows.nodes.size(); ++i) {
    const Eigen::Matrix3d& J = rows.blocks[i];
    const Eigen::Matrix3d& P = inv_diag[static_cast<size_t>(rows.nodes[i])];
    for (int r = 0; r < 3; ++r) w[r] += J.row(r).dot(P * J.row(r).transpose());
  }
  return w;
}

Eigen::Matrix3d contact_block(const ContactRows& rows, const std::vector<Eigen::Matrix3d>& inv_diag) {
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < rows.nodes.size(); ++i)
    W.noalias() += rows.blocks[i] * inv_diag[static_cast<size_t>(rows.nodes[i])] * rows.blocks[i].transpose();
  return W;
}

double normal_rows_product(const ContactRows& a, const ContactRows& b, const std::vector<Eigen::Matrix3d>& inv_diag) {
  // Node lists are ascending: walk both once.
  double product = 0.0;
  size_t i = 0, j = 0;
  while (i < a.nodes.size() && j < b.nodes.size()) {
    if (a.nodes[i] < b.nodes[j]) {
      ++i;
    } else if (b.nodes[j] < a.nodes[i]) {
      ++j;
    } else {
      product += a.blocks[i].row(0).dot(inv_diag[static_cast<size_t>(a.nodes[i])] * b.blocks[j].row(0).transpose());
      ++i;
      ++j;
    }
  }
  return product;
}

Eigen::Vector2d tangent_impulse(const ContactRows& rows, const ContactState& state) {
  switch (state.mode) {
    case ContactMode::sticking: return state.gamma;
    case ContactMode::sliding: return -rows.mu_kinetic * state.lambda_kinetic * state.slip;
    case ContactMode::inactive: break;
  }
  return Eigen::Vector2d::Zero();
}

double slip_direction_error(double friction_speed, const Eigen::Vector2d& u, const Eigen::Vector2d& slip) {
  const double speed = u.norm();
  if (speed == 0.0) return 0.0;
  return std::min(friction_speed, speed) * (u / speed - slip).norm();
}

}  // namespace recoil::sim
