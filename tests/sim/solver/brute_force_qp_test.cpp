// Frictionless random QPs: every method against brute-force enumeration of
// active sets (to 1e-6).
#include <gtest/gtest.h>

#include <iostream>

#include "tests/fixtures/problem_builders.h"
#include "tests/sim/solver/solver_test_support.h"

namespace recoil::sim {
namespace {

using solver_test::brute_force_normal;
using solver_test::solve_copy;
using solver_test::tight;

// Up to 4 nodes (12 DoF) and 8 contacts, each on one or two nodes (an
// embedded surface point), random normals and right-hand sides.
OwnedProblem random_normal_problem(std::mt19937& rng) {
  std::uniform_int_distribution<int> node_count(1, 4);
  const int nodes = node_count(rng);
  OwnedProblem out = random_system(nodes, 0.5, rng);
  std::uniform_int_distribution<int> contact_count(1, std::min(8, 3 * nodes));
  std::uniform_int_distribution<int> pick(0, nodes - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  const int m = contact_count(rng);
  for (int k = 0; k < m; ++k) {
    int a = pick(rng), b = pick(rng);
    std::vector<int> ids = {a};
    std::vector<double> weights = {1.0};
    if (b != a) {
      const double w = unit(rng);
      ids = {std::min(a, b), std::max(a, b)};
      weights = a < b ? std::vector<double>{w, 1.0 - w} : std::vector<double>{1.0 - w, w};
    }
    add_contact(out.problem, ids, weights, Eigen::Vector3d(normal(rng), normal(rng), normal(rng)), normal(rng), 0.0, 0.0);
  }
  return out;
}

TEST(SolverBruteForce, RandomFrictionlessQpsMatchEnumeration) {
  std::mt19937 rng(20240605);
  double worst[3] = {0.0, 0.0, 0.0};
  int checked = 0;
  for (int trial = 0; trial < 150; ++trial) {
    OwnedProblem owned = random_normal_problem(rng);
    const auto reference = brute_force_normal(owned.problem);
    ASSERT_TRUE(reference.has_value()) << "trial " << trial;
    ++checked;
    for (SolverMethod method : {SolverMethod::cr, SolverMethod::cr_plain, SolverMethod::pgs}) {
      const auto solution = solve_copy(owned.problem, tight(method));
      ASSERT_TRUE(solution.stats.converged) << to_string(method) << " trial " << trial;
      double err = (solution.dv - reference->dv).lpNorm<Eigen::Infinity>();
      for (size_t k = 0; k < solution.states.size(); ++k)
        err = std::max(err, std::abs(solution.states[k].lambda - reference->lambda[static_cast<Eigen::Index>(k)]));
      EXPECT_LT(err, 1e-6) << to_string(method) << " trial " << trial << " contacts " << owned.problem.rows.size();
      EXPECT_LT(solution.stats.kkt, 1e-8) << to_string(method) << " trial " << trial;
      worst[static_cast<int>(method)] = std::max(worst[static_cast<int>(method)], err);
    }
  }
  std::cout << "brute force: " << checked << " problems, worst |dv, lambda - reference|_inf: cr " << worst[0]
            << ", cr_plain " << worst[1] << ", pgs " << worst[2] << "\n";
}

}  // namespace
}  // namespace recoil::sim
