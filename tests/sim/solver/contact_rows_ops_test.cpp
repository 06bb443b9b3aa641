// The per-contact row kernels against dense matrices: the coupling of two
// contacts' normal rows through P_A^-1 (the parallel-row rule of
// constraint_evaluation.h rests on it).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "sim/solver/contact_rows_ops.h"
#include "sim/solver/problem_builders.h"
#include "tests/sim/solver/solver_test_support.h"

namespace recoil::sim {
namespace {

TEST(ContactRowsOps, NormalRowsProductMatchesDenseProduct) {
  std::mt19937 rng(7);
  OwnedProblem owned = random_system(5, 1.0, rng);
  ContactProblem& problem = owned.problem;
  // Two contacts sharing nodes 1 and 3 (weights and normals differ), one on nodes of its own.
  add_contact(problem, {0, 1, 3}, {0.2, 0.5, 0.3}, Eigen::Vector3d(0.3, 1.0, -0.2), 0.0, 0.5, 0.5);
  add_contact(problem, {1, 2, 3}, {0.6, 0.1, 0.3}, Eigen::Vector3d(-0.1, 1.0, 0.4), 0.0, 0.5, 0.5);
  add_contact(problem, {4}, {1.0}, Eigen::Vector3d(0.0, 0.0, 1.0), 0.0, 0.5, 0.5);
  const std::vector<Eigen::Matrix3d> inv_diag = inverse_diagonal_blocks(*problem.A);
  const int dofs = static_cast<int>(problem.b.size());
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(dofs, dofs);
  for (int i = 0; i < dofs / 3; ++i) P.block<3, 3>(3 * i, 3 * i) = inv_diag[static_cast<size_t>(i)];
  const Eigen::MatrixXd J = solver_test::dense_normal_rows(problem);
  const Eigen::MatrixXd coupling = J * P * J.transpose();
  for (size_t a = 0; a < problem.rows.size(); ++a)
    for (size_t b = 0; b < problem.rows.size(); ++b) {
      const double dense = coupling(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
      EXPECT_NEAR(normal_rows_product(problem.rows[a], problem.rows[b], inv_diag), dense, 1e-12 * (1.0 + std::abs(dense)))
          << a << ", " << b;
    }
  EXPECT_NEAR(normal_rows_product(problem.rows[0], problem.rows[0], inv_diag),
              effective_inverse_mass(problem.rows[0], inv_diag)[0], 1e-12);
  EXPECT_EQ(normal_rows_product(problem.rows[0], problem.rows[2], inv_diag), 0.0);
  EXPECT_NE(normal_rows_product(problem.rows[0], problem.rows[1], inv_diag), 0.0);
}

}  // namespace
}  // namespace recoil::sim
