// Solver behaviour: cr against pgs on frictional problems, the
// preconditioner, warm starts, the iteration cap and determinism.
#include <gtest/gtest.h>

#include <cstring>
#include <iostream>

#include "sim/solver/kkt_residual.h"
#include "sim/solver/problem_builders.h"
#include "tests/sim/solver/solver_test_support.h"

namespace recoil::sim {
namespace {

using solver_test::solve_copy;
using solver_test::tight;

// One contact per node (so the frictional solution is unique), random
// normals, right-hand sides and mu_s = mu_k.
OwnedProblem random_friction_problem(std::mt19937& rng) {
  std::uniform_int_distribution<int> node_count(1, 4);
  const int nodes = node_count(rng);
  OwnedProblem out = random_system(nodes, 1.0, rng);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> mu(0.1, 0.8);
  for (int i = 0; i < nodes; ++i) {
    const double friction = mu(rng);
    add_contact(out.problem, {i}, {1.0}, Eigen::Vector3d(normal(rng), normal(rng), normal(rng)), normal(rng),
                friction, friction);
    out.problem.rows.back().rhs_tangent = Eigen::Vector2d(normal(rng), normal(rng));
  }
  return out;
}

TEST(SolverConvergence, CrAgreesWithPgsOnRandomFrictionalProblems) {
  std::mt19937 rng(77);
  double worst = 0.0, worst_kkt_cr = 0.0, worst_kkt_pgs = 0.0;
  for (int trial = 0; trial < 60; ++trial) {
    OwnedProblem owned = random_friction_problem(rng);
    const auto cr = solve_copy(owned.problem, tight(SolverMethod::cr));
    const auto pgs = solve_copy(owned.problem, tight(SolverMethod::pgs));
    ASSERT_TRUE(cr.stats.converged) << "trial " << trial << " it " << cr.stats.iterations << " restarts " << cr.stats.restarts << " frozen " << cr.stats.frozen << " kkt " << cr.stats.kkt << " res " << cr.stats.residual;
    ASSERT_TRUE(pgs.stats.converged) << "trial " << trial;
    const double scale = std::max(1.0, pgs.dv.lpNorm<Eigen::Infinity>());
    const double err = (cr.dv - pgs.dv).lpNorm<Eigen::Infinity>() / scale;
    EXPECT_LT(err, 1e-6) << "trial " << trial << " sticking " << cr.stats.sticking << "/" << pgs.stats.sticking
                         << " sliding " << cr.stats.sliding << "/" << pgs.stats.sliding;
    worst = std::max(worst, err);
    worst_kkt_cr = std::max(worst_kkt_cr, cr.stats.kkt);
    worst_kkt_pgs = std::max(worst_kkt_pgs, pgs.stats.kkt);
  }
  std::cout << "cr vs pgs, 60 frictional problems: worst relative |dv difference| " << worst << ", worst KKT cr "
            << worst_kkt_cr << " pgs " << worst_kkt_pgs << " m/s\n";
}

// A jelly block of nodes with masses spread over four decades on the
// ground: the block-Jacobi preconditioner absorbs the mass spread.
OwnedProblem ill_conditioned_lattice() {
  std::mt19937 rng(5);
  return lattice_on_ground(4, 4, 3, 0.001, 1e4, 2000.0, 1.0 / 60.0, 0.5, 0.3, rng);
}

ContactSolverSettings bench_settings(SolverMethod method) {
  ContactSolverSettings s;
  s.method = method;
  s.tolerance = 1e-8;
  s.constraint_tolerance = 1e-8;
  s.max_iterations = 100000;
  return s;
}

TEST(SolverConvergence, PreconditionerCutsIterations) {
  OwnedProblem owned = ill_conditioned_lattice();
  const auto cr = solve_copy(owned.problem, bench_settings(SolverMethod::cr));
  const auto plain = solve_copy(owned.problem, bench_settings(SolverMethod::cr_plain));
  ASSERT_TRUE(cr.stats.converged);
  ASSERT_TRUE(plain.stats.converged);
  std::cout << "lattice 4x4x3, mass spread 1e4: iterations cr " << cr.stats.iterations << " (restarts "
            << cr.stats.restarts << ", kkt " << cr.stats.kkt << "), cr_plain " << plain.stats.iterations
            << " (restarts " << plain.stats.restarts << ", kkt " << plain.stats.kkt << ")\n";
  EXPECT_LT(cr.stats.iterations, plain.stats.iterations);
  const double scale = cr.dv.lpNorm<Eigen::Infinity>();
  EXPECT_LT((cr.dv - plain.dv).lpNorm<Eigen::Infinity>(), 1e-5 * scale) << "both reach the same solution";
}

TEST(SolverConvergence, WarmStartNeedsFewerIterations) {
  OwnedProblem owned = ill_conditioned_lattice();
  for (SolverMethod method : {SolverMethod::cr, SolverMethod::pgs}) {
    const ContactSolverSettings settings = bench_settings(method);
    ContactProblem cold = owned.problem;
    Eigen::VectorXd dv;
    const auto first = solve_contacts(cold, settings, dv);
    ContactProblem warm = owned.problem;
    warm.states = cold.states;  // last step's multipliers and friction states
    const auto second = solve_contacts(warm, settings, dv);
    std::cout << to_string(method) << ": cold " << first.iterations << " iterations, warm " << second.iterations
              << "\n";
    ASSERT_TRUE(first.converged && second.converged);
    EXPECT_LT(second.iterations, first.iterations) << to_string(method);
  }
}

TEST(SolverConvergence, IterationCapReportsNotConverged) {
  OwnedProblem owned = ill_conditioned_lattice();
  for (SolverMethod method : {SolverMethod::cr, SolverMethod::cr_plain, SolverMethod::pgs}) {
    ContactSolverSettings settings = bench_settings(method);
    settings.max_iterations = 5;
    const auto s = solve_copy(owned.problem, settings);
    EXPECT_FALSE(s.stats.converged) << to_string(method);
    EXPECT_LE(s.stats.iterations, 5) << to_string(method);
    EXPECT_EQ(s.dv.size(), owned.problem.b.size());
  }
}

TEST(SolverConvergence, TwoRunsAreBitIdentical) {
  OwnedProblem owned = ill_conditioned_lattice();
  for (SolverMethod method : {SolverMethod::cr, SolverMethod::cr_plain, SolverMethod::pgs}) {
    const auto a = solve_copy(owned.problem, bench_settings(method));
    const auto b = solve_copy(owned.problem, bench_settings(method));
    ASSERT_EQ(a.dv.size(), b.dv.size());
    EXPECT_EQ(std::memcmp(a.dv.data(), b.dv.data(), sizeof(double) * static_cast<size_t>(a.dv.size())), 0)
        << to_string(method);
    EXPECT_EQ(a.stats.iterations, b.stats.iterations);
  }
}

}  // namespace
}  // namespace recoil::sim
