// The per-contact row kernels against dense matrices: the coupling of two
// contacts' normal rows through P_A^-1 (the parallel-row rule of
// constraint_evaluation.h rests on it) and the contact blocks, with and
// without the rigid-mode term of momentum_preconditioner.h.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <limits>
#include <random>

#include "sim/solver/contact_rows_ops.h"
#include "tests/fixtures/problem_builders.h"
#include "tests/sim/solver/solver_test_support.h"

namespace recoil::sim {
namespace {

// P_A^-1 as a dense matrix, one column per unit vector.
Eigen::MatrixXd dense_preconditioner(const MomentumPreconditioner& P, int dofs) {
  Eigen::MatrixXd out(dofs, dofs);
  Eigen::VectorXd column(dofs);
  for (int i = 0; i < dofs; ++i) {
    P.apply(Eigen::VectorXd::Unit(dofs, i), column);
    out.col(i) = column;
  }
  return out;
}

// Three contacts on a random 5-node system: two sharing nodes 1 and 3
// (weights and normals differ), one on a node of its own.
OwnedProblem three_contacts(std::mt19937& rng) {
  OwnedProblem owned = random_system(5, 1.0, rng);
  add_contact(owned.problem, {0, 1, 3}, {0.2, 0.5, 0.3}, Eigen::Vector3d(0.3, 1.0, -0.2), 0.0, 0.5, 0.5);
  add_contact(owned.problem, {1, 2, 3}, {0.6, 0.1, 0.3}, Eigen::Vector3d(-0.1, 1.0, 0.4), 0.0, 0.5, 0.5);
  add_contact(owned.problem, {4}, {1.0}, Eigen::Vector3d(0.0, 0.0, 1.0), 0.0, 0.5, 0.5);
  return owned;
}

// normal_rows_product and effective_inverse_mass against J P J^T.
void expect_kernels_match_dense(const ContactProblem& problem, const MomentumPreconditioner& P) {
  const int dofs = static_cast<int>(problem.b.size());
  const Eigen::MatrixXd dense_P = dense_preconditioner(P, dofs);
  const Eigen::MatrixXd J = solver_test::dense_normal_rows(problem);
  const Eigen::MatrixXd coupling = J * dense_P * J.transpose();
  for (size_t a = 0; a < problem.rows.size(); ++a)
    for (size_t b = 0; b < problem.rows.size(); ++b) {
      const double dense = coupling(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
      EXPECT_NEAR(normal_rows_product(problem.rows[a], problem.rows[b], P), dense, 1e-12 * (1.0 + std::abs(dense)))
          << a << ", " << b;
    }
  for (const ContactRows& rows : problem.rows) {
    Eigen::MatrixXd Jk = Eigen::MatrixXd::Zero(3, dofs);
    for (size_t i = 0; i < rows.nodes.size(); ++i) Jk.middleCols<3>(3 * rows.nodes[i]) = rows.blocks[i];
    const Eigen::Matrix3d dense = Jk * dense_P * Jk.transpose();
    EXPECT_LT((effective_inverse_mass(rows, P) - dense.diagonal()).norm(), 1e-12 * (1.0 + dense.norm()));
  }
}

TEST(ContactRowsOps, KernelsMatchDenseBlockJacobi) {
  std::mt19937 rng(7);
  OwnedProblem owned = three_contacts(rng);
  const ContactProblem& problem = owned.problem;
  const MomentumPreconditioner P(*problem.A);
  expect_kernels_match_dense(problem, P);
  EXPECT_NEAR(normal_rows_product(problem.rows[0], problem.rows[0], P), effective_inverse_mass(problem.rows[0], P)[0],
              1e-12);
  EXPECT_EQ(normal_rows_product(problem.rows[0], problem.rows[2], P), 0.0);
  EXPECT_NE(normal_rows_product(problem.rows[0], problem.rows[1], P), 0.0);
}

// Two bodies that A does not couple (springs inside each only): nodes 0-3,
// and nodes 4-5, a pair on a line (no rotation about it: five rigid modes).
// One contact spans both bodies.
TEST(ContactRowsOps, KernelsMatchDenseWithRigidModes) {
  std::mt19937 rng(7);
  OwnedProblem owned;
  owned.A = mass_spring_matrix({1.0, 2.0, 1.5, 0.5, 1.0, 3.0}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {4, 5}}, 50.0);
  owned.problem.A = owned.A.get();
  owned.problem.b = Eigen::VectorXd::Zero(18);
  ContactProblem& problem = owned.problem;
  add_contact(problem, {0, 1, 3}, {0.2, 0.5, 0.3}, Eigen::Vector3d(0.3, 1.0, -0.2), 0.0, 0.5, 0.5);
  add_contact(problem, {1, 2, 3}, {0.6, 0.1, 0.3}, Eigen::Vector3d(-0.1, 1.0, 0.4), 0.0, 0.5, 0.5);
  add_contact(problem, {4}, {1.0}, Eigen::Vector3d(0.3, 0.5, 1.0), 0.0, 0.5, 0.5);
  add_contact(problem, {2, 5}, {1.0, -1.0}, Eigen::Vector3d(1.0, 0.2, 0.4), 0.0, 0.5, 0.5);
  std::uniform_real_distribution<double> coordinate(-0.5, 0.5);
  RigidModeNodes first, second;
  for (int node = 0; node < 4; ++node) {
    first.nodes.push_back(node);
    first.positions.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
  }
  second.nodes = {4, 5};
  second.positions = {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.3, 0.0)};
  const MomentumPreconditioner P(*problem.A, {first, second});
  expect_kernels_match_dense(problem, P);
  // Contacts on different bodies share nothing; the spanning one couples to both.
  EXPECT_EQ(normal_rows_product(problem.rows[0], problem.rows[2], P), 0.0);
  EXPECT_NE(normal_rows_product(problem.rows[0], problem.rows[3], P), 0.0);
  EXPECT_NE(normal_rows_product(problem.rows[2], problem.rows[3], P), 0.0);
  // Contacts on distinct nodes of one body couple through its rigid motion.
  add_contact(problem, {0}, {1.0}, Eigen::Vector3d(0.0, 1.0, 0.0), 0.0, 0.5, 0.5);
  add_contact(problem, {2}, {1.0}, Eigen::Vector3d(0.0, 1.0, 0.0), 0.0, 0.5, 0.5);
  EXPECT_GT(normal_rows_product(problem.rows[4], problem.rows[5], P), 0.0);
  // The pair's coarse term: a rotation about its own line is no motion of it.
  const MomentumPreconditioner::CoarseMatrix& S_inv = P.coarse_inverse(1);
  EXPECT_TRUE(S_inv.allFinite());
  EXPECT_LT((S_inv * (Eigen::Matrix<double, 6, 1>() << 0, 0, 0, 0, 1, 0).finished()).norm(), 1e-12);
}

// On a rigid motion of a body, the coarse term inverts A: (P - D^-1) (A Z c) = Z c.
TEST(MomentumPreconditioner, ExactOnRigidModes) {
  std::mt19937 rng(11);
  OwnedProblem owned = random_system(6, 1.0, rng);
  const BlockSparseMatrix& A = *owned.A;
  std::uniform_real_distribution<double> coordinate(-0.5, 0.5);
  RigidModeNodes body;
  for (int node = 0; node < 6; ++node) {
    body.nodes.push_back(node);
    body.positions.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
  }
  const MomentumPreconditioner P(A, {body});
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& x : body.positions) centroid += x / 6.0;
  const Eigen::Vector3d t(0.3, -1.0, 0.2), w(2.0, 0.5, -1.5);
  Eigen::VectorXd motion(18), force, back(18);
  for (int node = 0; node < 6; ++node) motion.segment<3>(3 * node) = t + w.cross(body.positions[static_cast<size_t>(node)] - centroid);
  A.multiply(motion, force);
  P.apply(force, back);
  // The additive form adds D^-1 A Z c on top; subtract it to see the coarse part alone.
  const MomentumPreconditioner jacobi(A);
  Eigen::VectorXd local(18);
  jacobi.apply(force, local);
  EXPECT_LT((back - local - motion).norm(), 1e-10 * motion.norm());
  // The squared norm, whole and stopped early.
  EXPECT_NEAR(P.applied_squared_norm(force, std::numeric_limits<double>::infinity()), back.squaredNorm(),
              1e-12 * back.squaredNorm());
  const double partial = P.applied_squared_norm(force, 1e-3 * back.squaredNorm());
  EXPECT_GT(partial, 1e-3 * back.squaredNorm());
  EXPECT_LE(partial, back.squaredNorm() * (1.0 + 1e-12));
}

}  // namespace
}  // namespace recoil::sim
