// The assembled system: BlockSparseMatrix against Eigen, symmetry and
// definiteness of A, the PCG solve against a direct solve, and pinned rows.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <iostream>
#include <random>

#include "sim/fem/pcg.h"
#include "tests/sim/fem/fem_scenes.h"

namespace recoil::sim {
namespace {

TEST(System, BlockSparseMatchesEigenAndPcgMatchesDirectSolve) {
  WorldDesc desc;
  desc.dt = 0.01;
  Material m = test_scenes::soft_material(MaterialModel::neo_hookean);
  m.damping_ratio = 0.2;
  desc.bodies.push_back(test_scenes::box_body({0.3, 0.1, 0.1}, 6, m));
  desc.bodies.back().pinned = PinBox{Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(-0.149, 1, 1)};
  World world(desc);
  Eigen::VectorXd x = world.positions();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += 0.01 * u(rng);
  world.set_state(x, world.velocities());
  world.step();  // assembles A at the perturbed state

  const BlockSparseMatrix& A = world.system_matrix();
  const Eigen::SparseMatrix<double> S = A.to_eigen();
  const Eigen::SparseMatrix<double> St = S.transpose();
  EXPECT_LT((S - St).norm(), 1e-12 * S.norm());
  Eigen::VectorXd probe(A.rows()), y;
  for (Eigen::Index i = 0; i < probe.size(); ++i) probe[i] = u(rng);
  A.multiply(probe, y);
  EXPECT_LT((y - S * probe).norm(), 1e-12 * y.norm());

  // Pinned nodes: identity rows and columns.
  const DeformableBody& body = world.deformable_body(0);
  for (int n = 0; n < body.num_nodes; ++n)
    if (body.pinned[static_cast<size_t>(n)]) {
      EXPECT_EQ(A.diagonal_block(n), Eigen::Matrix3d::Identity());
      EXPECT_EQ(S.col(3 * n).norm(), 1.0);
    }

  Eigen::VectorXd b(A.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = u(rng);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(S);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  EXPECT_GT(ldlt.vectorD().minCoeff(), 0.0);  // SPD
  const Eigen::VectorXd direct = ldlt.solve(b);
  // Block Jacobi alone, and with the body's rigid modes: the same answer.
  RigidModeNodes modes;
  for (int n = 0; n < body.num_nodes; ++n)
    if (!body.pinned[static_cast<size_t>(n)]) {
      modes.nodes.push_back(body.node_offset + n);
      modes.positions.push_back(world.positions().segment<3>(3 * (body.node_offset + n)));
    }
  const MomentumPreconditioner jacobi(A), two_level(A, {modes});
  Eigen::VectorXd dv;
  for (const MomentumPreconditioner* P : {&jacobi, &two_level}) {
    const PcgResult r = solve_pcg(A, *P, b, dv, {1e-10, 5000});
    std::cout << "PCG: " << r.iterations << " iterations, residual " << r.relative_residual << ", |x - x_direct| / |x| "
              << (dv - direct).norm() / direct.norm() << "\n";
    EXPECT_TRUE(r.converged);
    EXPECT_LT((dv - direct).norm(), 1e-6 * direct.norm());
  }

  // An iteration cap is reported, not hidden.
  const PcgResult capped = solve_pcg(A, jacobi, b, dv, {1e-14, 3});
  EXPECT_FALSE(capped.converged);
  EXPECT_EQ(capped.iterations, 3);
}

// A free, nearly rigid body at a long step: D^-1 alone sees its rigid
// motions h^2 k / m ~ 1e9 times too stiff, and PCG pays for that in
// iterations; with the body's rigid modes in P_A^-1 it does not.
TEST(System, RigidModesCutPcgIterationsOnAStiffBody) {
  WorldDesc desc;
  desc.dt = 0.1;
  Material m = test_scenes::soft_material();
  m.youngs_modulus = 1e12;
  desc.bodies.push_back(test_scenes::box_body({0.2, 0.2, 0.2}, 4, m));
  World world(desc);
  const Eigen::VectorXd x = world.positions();  // where step() assembles A
  world.step();
  const BlockSparseMatrix& A = world.system_matrix();
  const DeformableBody& body = world.deformable_body(0);
  RigidModeNodes modes;
  for (int n = 0; n < body.num_nodes; ++n) {
    modes.nodes.push_back(body.node_offset + n);
    modes.positions.push_back(x.segment<3>(3 * (body.node_offset + n)));
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd b(A.rows()), dv_jacobi, dv_modes;
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = u(rng);
  const PcgResult jacobi = solve_pcg(A, MomentumPreconditioner(A), b, dv_jacobi, {1e-8, 20000});
  const PcgResult with_modes = solve_pcg(A, MomentumPreconditioner(A, {modes}), b, dv_modes, {1e-8, 20000});
  std::cout << "stiff body PCG iterations: block Jacobi " << jacobi.iterations << ", with rigid modes "
            << with_modes.iterations << "\n";
  EXPECT_TRUE(with_modes.converged);
  EXPECT_LT(with_modes.iterations, jacobi.iterations / 2);
  EXPECT_LT((dv_modes - dv_jacobi).norm(), 1e-4 * dv_modes.norm());
}

}  // namespace
}  // namespace recoil::sim
