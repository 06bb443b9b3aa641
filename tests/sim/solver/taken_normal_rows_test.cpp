// The hold-back's index of taken rows (taken_normal_rows.h) decides as
// measuring every pair would, including rows that share no DoF node and
// couple through a stiff body's rigid motions alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "sim/solver/contact_rows_ops.h"
#include "sim/solver/taken_normal_rows.h"
#include "tests/fixtures/problem_builders.h"

namespace recoil::sim {
namespace {

TEST(TakenNormalRows, DecidesAsMeasuringEveryPair) {
  constexpr double kCosine = 0.9;
  int held_back = 0, held_without_shared_node = 0, decisions = 0;
  for (double stiffness : {1.0, 1e3, 1e6}) {
    std::mt19937 rng(11);
    OwnedProblem owned = lattice_on_ground(3, 3, 2, 1.0, 1.0, stiffness, 0.01, 0.5, 0.0, rng);
    const int nodes = owned.problem.A->block_rows();
    // One body of every node, so P_A^-1 has its rigid-motion term.
    RigidModeNodes body;
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    for (int i = 0; i < nodes; ++i) {
      body.nodes.push_back(i);
      body.positions.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    }
    const MomentumPreconditioner P(*owned.problem.A, {body});
    // Contacts on one or two random nodes, with normals near +z or random.
    std::uniform_int_distribution<int> node(0, nodes - 1);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int c = 0; c < 60; ++c) {
      const int a = node(rng), b = node(rng);
      const Eigen::Vector3d n = c % 2 == 0 ? Eigen::Vector3d(0.05 * normal(rng), 0.05 * normal(rng), 1.0)
                                           : Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
      if (a == b) {
        add_contact(owned.problem, {a}, {1.0}, n.normalized(), 0.0, 0.5, 0.5);
      } else {
        add_contact(owned.problem, {std::min(a, b), std::max(a, b)}, {0.5, 0.5}, n.normalized(), 0.0, 0.5, 0.5);
      }
    }
    const ContactProblem& problem = owned.problem;
    const int m = static_cast<int>(problem.rows.size());
    std::vector<Eigen::Vector3d> inverse_masses;
    for (int k = 0; k < m; ++k) inverse_masses.push_back(effective_inverse_mass(problem.rows[k], P));
    TakenNormalRows taken(problem, inverse_masses, P, kCosine);
    std::vector<int> taken_list;
    for (int k = 0; k < m; ++k) {
      bool parallel = false, through_shared_node = false;
      for (int t : taken_list) {
        const double w_k = inverse_masses[static_cast<size_t>(k)][0], w_t = inverse_masses[static_cast<size_t>(t)][0];
        if (normal_rows_product(problem.rows[k], problem.rows[t], P) > kCosine * std::sqrt(w_k * w_t)) {
          parallel = true;
          const auto& a = problem.rows[k].nodes;
          const auto& b = problem.rows[t].nodes;
          const auto in_b = [&](int i) { return std::count(b.begin(), b.end(), i) > 0; };
          through_shared_node = through_shared_node || std::any_of(a.begin(), a.end(), in_b);
        }
      }
      ASSERT_EQ(taken.parallel_to_taken(k), parallel) << "stiffness " << stiffness << ", contact " << k;
      ++decisions;
      if (parallel) {
        ++held_back;
        if (!through_shared_node) ++held_without_shared_node;
      } else {
        taken.take(k);
        taken_list.push_back(k);
      }
    }
  }
  std::cout << decisions << " decisions, " << held_back << " held back, " << held_without_shared_node
            << " of them by rows sharing no node\n";
  EXPECT_GT(held_without_shared_node, 0);
  EXPECT_LT(held_back, decisions);
}

}  // namespace
}  // namespace recoil::sim
