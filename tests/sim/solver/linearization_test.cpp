// The solver honours ContactLinearization (Algorithm 1's outer loop): new
// contacts found at the predicted positions join the solve, and
// re-linearised right-hand sides are solved for before returning.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/fixtures/problem_builders.h"
#include "tests/sim/solver/solver_test_support.h"

namespace recoil::sim {
namespace {

using solver_test::kG;
using solver_test::kH;

// Two free particles (masses 1 and 3 kg) falling onto the ground z = 0.
// Particle 0 starts with a contact; particle 1 has none until the solver's
// prediction shows it moving down, when `add_new_contacts` adds it. The
// first re-linearisation asks particle 0's contact for a separating
// velocity of 0.1 m/s, as a closing gap measured at x* would.
class FakeLinearization : public ContactLinearization {
 public:
  int add_calls = 0, relinearize_calls = 0;

  int add_new_contacts(const Eigen::VectorXd& dv, ContactProblem& problem) override {
    ++add_calls;
    if (problem.rows.size() > 1 || dv[5] >= 0.0) return 0;
    add_contact(problem, {1}, {1.0}, Eigen::Vector3d::UnitZ(), 0.0, 0.5, 0.5);
    return 1;
  }

  double relinearize(const Eigen::VectorXd&, ContactProblem& problem) override {
    ++relinearize_calls;
    if (relinearize_calls > 1) return 0.0;
    problem.rows[0].rhs_normal = 0.1;
    return 0.1;
  }
};

OwnedProblem two_particles() {
  OwnedProblem out;
  out.A = std::make_unique<BlockSparseMatrix>(2, std::vector<std::pair<int, int>>{});
  out.A->block(out.A->find(0, 0)) = 1.0 * Eigen::Matrix3d::Identity();
  out.A->block(out.A->find(1, 1)) = 3.0 * Eigen::Matrix3d::Identity();
  out.problem.A = out.A.get();
  out.problem.b = Eigen::VectorXd::Zero(6);
  out.problem.b[2] = -kH * 1.0 * kG;
  out.problem.b[5] = -kH * 3.0 * kG;
  add_contact(out.problem, {0}, {1.0}, Eigen::Vector3d::UnitZ(), 0.0, 0.5, 0.5);
  return out;
}

TEST(SolverLinearization, NewContactsAndRelinearizationAreHonoured) {
  for (SolverMethod method : {SolverMethod::cr, SolverMethod::cr_plain, SolverMethod::pgs}) {
    OwnedProblem owned = two_particles();
    FakeLinearization fake;
    Eigen::VectorXd dv;
    const auto stats = solve_contacts(owned.problem, solver_test::tight(method), dv, &fake);
    std::cout << to_string(method) << ": new contacts " << stats.new_contacts << ", relinearizations "
              << stats.relinearizations << ", dv_z " << dv[2] << " " << dv[5] << ", iterations " << stats.iterations
              << "\n";
    ASSERT_TRUE(stats.converged) << to_string(method);
    EXPECT_EQ(stats.new_contacts, 1) << to_string(method);
    EXPECT_EQ(stats.relinearizations, 2) << to_string(method);
    ASSERT_EQ(owned.problem.states.size(), 2u);
    EXPECT_NEAR(dv[2], 0.1, 1e-9) << to_string(method) << ": re-linearised row solved";
    EXPECT_NEAR(dv[5], 0.0, 1e-9) << to_string(method) << ": the new contact holds particle 1";
    EXPECT_NEAR(owned.problem.states[1].lambda, kH * 3.0 * kG, 1e-9) << to_string(method);
    EXPECT_EQ(stats.active, 2) << to_string(method);
    EXPECT_LT(stats.kkt, 1e-9) << to_string(method);
  }
}

}  // namespace
}  // namespace recoil::sim
