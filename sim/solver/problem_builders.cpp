#include "sim/solver/problem_builders.h"

#include <Eigen/Geometry>
#include <cmath>

#include "core/check.h"
#include "sim/geometry/skew.h"

namespace recoil::sim {

namespace {

std::unique_ptr<BlockSparseMatrix> dense_block_matrix(const Eigen::MatrixXd& dense) {
  const int nodes = static_cast<int>(dense.rows()) / 3;
  std::vector<std::pair<int, int>> pairs;
  for (int r = 0; r < nodes; ++r)
    for (int c = 0; c < nodes; ++c) pairs.emplace_back(r, c);
  auto A = std::make_unique<BlockSparseMatrix>(nodes, pairs);
  for (int r = 0; r < nodes; ++r)
    for (int c = 0; c < nodes; ++c) A->block(A->find(r, c)) = dense.block<3, 3>(3 * r, 3 * c);
  return A;
}

}  // namespace

OwnedProblem random_system(int nodes, double shift, std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const int n = 3 * nodes;
  Eigen::MatrixXd L(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) L(i, j) = normal(rng);
  const Eigen::MatrixXd dense = L * L.transpose() / n + shift * Eigen::MatrixXd::Identity(n, n);
  OwnedProblem out;
  out.A = dense_block_matrix(dense);
  out.problem.A = out.A.get();
  out.problem.b.resize(n);
  for (int i = 0; i < n; ++i) out.problem.b[i] = normal(rng);
  return out;
}

Eigen::Matrix3d contact_frame(const Eigen::Vector3d& normal, double weight) {
  const Eigen::Vector3d nn = normal.normalized();
  const Eigen::Vector3d helper = std::abs(nn.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d t1 = (helper - helper.dot(nn) * nn).normalized();
  const Eigen::Vector3d t2 = nn.cross(t1);
  Eigen::Matrix3d frame;
  frame.row(0) = nn;
  frame.row(1) = t1;
  frame.row(2) = t2;
  return weight * frame;
}

void add_contact(ContactProblem& problem, const std::vector<int>& nodes, const std::vector<double>& weights,
                 const Eigen::Vector3d& normal, double rhs_normal, double mu_static, double mu_kinetic) {
  RECOIL_CHECK(nodes.size() == weights.size());
  ContactRows rows;
  rows.nodes = nodes;
  for (double w : weights) rows.blocks.push_back(contact_frame(normal, w));
  rows.rhs_normal = rhs_normal;
  rows.mu_static = mu_static;
  rows.mu_kinetic = mu_kinetic;
  problem.rows.push_back(rows);
  problem.states.emplace_back();
}

OwnedProblem particle_on_incline(double mass, double theta, double g, double h, const Eigen::Vector2d& v_t,
                                 double mu_static, double mu_kinetic) {
  OwnedProblem out;
  out.A = std::make_unique<BlockSparseMatrix>(1, std::vector<std::pair<int, int>>{});
  out.A->block(out.A->find(0, 0)) = mass * Eigen::Matrix3d::Identity();
  out.problem.A = out.A.get();
  // World frame: gravity along -z; the plane's normal tilted by theta about x.
  out.problem.b = h * mass * Eigen::Vector3d(0.0, 0.0, -g);
  const Eigen::Vector3d normal(0.0, -std::sin(theta), std::cos(theta));
  ContactRows rows;
  rows.nodes = {0};
  Eigen::Matrix3d frame;
  frame.row(0) = normal;
  frame.row(1) = Eigen::Vector3d(0.0, std::cos(theta), std::sin(theta));  // t1: up the slope
  frame.row(2) = Eigen::Vector3d::UnitX();                                // t2: level, across the slope
  rows.blocks = {frame};
  rows.rhs_normal = 0.0;
  rows.rhs_tangent = -v_t;
  rows.mu_static = mu_static;
  rows.mu_kinetic = mu_kinetic;
  out.problem.rows.push_back(rows);
  out.problem.states.emplace_back();
  return out;
}

std::unique_ptr<BlockSparseMatrix> mass_spring_matrix(const std::vector<double>& masses,
                                                      const std::vector<std::pair<int, int>>& springs,
                                                      double h2_stiffness) {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [a, b] : springs) {
    pairs.emplace_back(a, b);
    pairs.emplace_back(b, a);
  }
  const int nodes = static_cast<int>(masses.size());
  auto A = std::make_unique<BlockSparseMatrix>(nodes, pairs);
  for (int i = 0; i < nodes; ++i) A->block(A->find(i, i)) = masses[static_cast<size_t>(i)] * Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d spring = h2_stiffness * Eigen::Matrix3d::Identity();
  for (const auto& [a, b] : springs) {
    A->block(A->find(a, a)) += spring;
    A->block(A->find(b, b)) += spring;
    A->block(A->find(a, b)) -= spring;
    A->block(A->find(b, a)) -= spring;
  }
  return A;
}

OwnedProblem lattice_on_ground(int nx, int ny, int nz, double mass, double mass_ratio, double stiffness, double h,
                               double mu, double drift, std::mt19937& rng) {
  const auto index = [&](int i, int j, int k) { return (k * ny + j) * nx + i; };
  const int nodes = nx * ny * nz;
  std::vector<std::pair<int, int>> springs;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (i + 1 < nx) springs.emplace_back(index(i, j, k), index(i + 1, j, k));
        if (j + 1 < ny) springs.emplace_back(index(i, j, k), index(i, j + 1, k));
        if (k + 1 < nz) springs.emplace_back(index(i, j, k), index(i, j, k + 1));
      }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> masses(static_cast<size_t>(nodes));
  for (double& m : masses) m = mass * std::pow(mass_ratio, unit(rng));
  const double g = 9.81;
  OwnedProblem out;
  out.A = mass_spring_matrix(masses, springs, h * h * stiffness);
  out.problem.b.resize(3 * nodes);
  for (int i = 0; i < nodes; ++i)
    out.problem.b.segment<3>(3 * i) = h * masses[static_cast<size_t>(i)] * Eigen::Vector3d(0.0, 0.0, -g);
  out.problem.A = out.A.get();
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      // Resting on the ground (rhs_normal = 0) and sliding along +x at `drift`.
      add_contact(out.problem, {index(i, j, 0)}, {1.0}, Eigen::Vector3d::UnitZ(), 0.0, mu, mu);
      const Eigen::Matrix3d frame = contact_frame(Eigen::Vector3d::UnitZ());
      out.problem.rows.back().rhs_tangent = -(frame.bottomRows<2>() * Eigen::Vector3d(drift, 0.0, 0.0));
    }
  return out;
}

OwnedProblem rigid_box_on_ground(const Eigen::Vector3d& size, double mass, double yaw, double g, double h,
                                 const Eigen::Vector3d& velocity, double mu_static, double mu_kinetic) {
  OwnedProblem out;
  out.A = std::make_unique<BlockSparseMatrix>(2, std::vector<std::pair<int, int>>{});
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d sq = size.cwiseProduct(size);
  const Eigen::Vector3d body_inertia = mass / 12.0 * Eigen::Vector3d(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y());
  out.A->block(out.A->find(0, 0)) = mass * Eigen::Matrix3d::Identity();
  out.A->block(out.A->find(1, 1)) = R * body_inertia.asDiagonal() * R.transpose();
  out.problem.A = out.A.get();
  out.problem.b = Eigen::VectorXd::Zero(6);
  out.problem.b[2] = -h * mass * g;
  const Eigen::Matrix3d F = contact_frame(Eigen::Vector3d::UnitZ());
  for (int corner = 0; corner < 4; ++corner) {
    const Eigen::Vector3d local(corner & 1 ? 0.5 * size.x() : -0.5 * size.x(),
                                corner & 2 ? 0.5 * size.y() : -0.5 * size.y(), -0.5 * size.z());
    const Eigen::Vector3d r = R * local;
    ContactRows rows;
    rows.nodes = {0, 1};
    rows.blocks = {F, -F * skew(r)};
    rows.rhs_normal = -velocity.z();
    rows.rhs_tangent = -(F.bottomRows<2>() * velocity);
    rows.mu_static = mu_static;
    rows.mu_kinetic = mu_kinetic;
    out.problem.rows.push_back(rows);
    out.problem.states.emplace_back();
  }
  return out;
}

}  // namespace recoil::sim
