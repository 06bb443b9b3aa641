#include "sim/solver/contact_rows_ops.h"

#include <algorithm>
#include <array>

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

ProblemPreconditioner::ProblemPreconditioner(const ContactProblem& problem) : m_used(problem.preconditioner) {
  if (m_used != nullptr) return;
  RECOIL_CHECK(problem.A != nullptr);
  m_own.emplace(*problem.A);
  m_used = &*m_own;
}

ContactRowModes contact_row_modes(const ContactRows& rows, const MomentumPreconditioner& P) {
  ContactRowModes out;
  for (size_t i = 0; i < rows.nodes.size(); ++i) {
    const int b = P.body_of(rows.nodes[i]);
    if (b < 0) continue;
    int slot = 0;
    while (slot < out.count && out.body[static_cast<size_t>(slot)] != b) ++slot;
    if (slot == out.count) {
      RECOIL_CHECK(out.count < 2, "a contact touches the rigid modes of more than two bodies");
      out.body[static_cast<size_t>(slot)] = b;
      out.rows_times_modes[static_cast<size_t>(slot)].setZero();
      ++out.count;
    }
    out.rows_times_modes[static_cast<size_t>(slot)].noalias() += rows.blocks[i] * P.mode_block(rows.nodes[i]);
  }
  return out;
}

Eigen::Vector3d effective_inverse_mass(const ContactRows& rows, const MomentumPreconditioner& P) {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < rows.nodes.size(); ++i) {
    const Eigen::Matrix3d& J = rows.blocks[i];
    const Eigen::Matrix3d& D = P.diagonal_inverse(rows.nodes[i]);
    for (int r = 0; r < 3; ++r) w[r] += J.row(r).dot(D * J.row(r).transpose());
  }
  const ContactRowModes modes = contact_row_modes(rows, P);
  for (size_t slot = 0; slot < static_cast<size_t>(modes.count); ++slot) {
    const MomentumPreconditioner::ModeBlock& JZ = modes.rows_times_modes[slot];
    w += (JZ * P.coarse_inverse(modes.body[slot]) * JZ.transpose()).diagonal();
  }
  return w;
}

NormalRowModes normal_row_modes(const ContactRows& rows, const MomentumPreconditioner& P) {
  const ContactRowModes modes = contact_row_modes(rows, P);
  NormalRowModes out;
  out.count = modes.count;
  out.body = modes.body;
  for (size_t slot = 0; slot < static_cast<size_t>(modes.count); ++slot)
    out.row[slot] = modes.rows_times_modes[slot].row(0);
  return out;
}

double normal_rows_product(const ContactRows& a, const ContactRows& b, const MomentumPreconditioner& P) {
  return normal_rows_product(a, normal_row_modes(a, P), b, normal_row_modes(b, P), P);
}

double normal_rows_product(const ContactRows& a, const NormalRowModes& modes_a, const ContactRows& b,
                           const NormalRowModes& modes_b, const MomentumPreconditioner& P) {
  // Node lists are ascending: walk both once.
  double product = 0.0;
  size_t i = 0, j = 0;
  while (i < a.nodes.size() && j < b.nodes.size()) {
    if (a.nodes[i] < b.nodes[j]) {
      ++i;
    } else if (b.nodes[j] < a.nodes[i]) {
      ++j;
    } else {
      product += a.blocks[i].row(0).dot(P.diagonal_inverse(a.nodes[i]) * b.blocks[j].row(0).transpose());
      ++i;
      ++j;
    }
  }
  for (size_t sa = 0; sa < static_cast<size_t>(modes_a.count); ++sa)
    for (size_t sb = 0; sb < static_cast<size_t>(modes_b.count); ++sb)
      if (modes_a.body[sa] == modes_b.body[sb])
        product += modes_a.row[sa].dot(P.coarse_inverse(modes_a.body[sa]) * modes_b.row[sb].transpose());
  return product;
}

double normal_row_rigid_part(const NormalRowModes& modes, const MomentumPreconditioner& P) {
  double part = 0.0;
  for (size_t slot = 0; slot < static_cast<size_t>(modes.count); ++slot)
    part += modes.row[slot].dot(P.coarse_inverse(modes.body[slot]) * modes.row[slot].transpose());
  return part;
}

double sliding_mu(const ContactRows& rows, const ContactState& state) {
  return state.impending ? rows.mu_static : rows.mu_kinetic;
}

Eigen::Vector2d tangent_impulse(const ContactRows& rows, const ContactState& state) {
  switch (state.mode) {
    case ContactMode::sticking: return state.gamma;
    case ContactMode::sliding: return -sliding_mu(rows, state) * state.lambda_kinetic * state.slip;
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
