// ContactSoftness: redundant rows get one split of the impulse, and a
// contact whose load is steady (warm start = solution) holds exactly.
#include <gtest/gtest.h>

#include "sim/solver/kkt_residual.h"
#include "tests/fixtures/problem_builders.h"
#include "tests/sim/solver/solver_test_support.h"

namespace recoil::sim {
namespace {

using solver_test::kG;
using solver_test::kH;

// A 2 kg particle resting on the ground through two identical normal rows
// (frictionless): without softness any split of m g h between them solves it.
OwnedProblem particle_on_two_rows(double softness) {
  OwnedProblem owned = particle_on_incline(2.0, 0.0, kG, kH, Eigen::Vector2d::Zero(), 0.0, 0.0);
  add_contact(owned.problem, {0}, {1.0}, Eigen::Vector3d::UnitZ(), 0.0, 0.0, 0.0);
  owned.problem.softness.normal = softness;
  return owned;
}

TEST(ContactSoftness, RedundantRowsShareTheImpulseEqually) {
  const double s = 0.01, mass = 2.0;
  for (SolverMethod method : {SolverMethod::cr, SolverMethod::pgs}) {
    OwnedProblem owned = particle_on_two_rows(s);
    Eigen::VectorXd dv;
    const ContactSolverStats stats = solve_contacts(owned.problem, solver_test::tight(method), dv);
    EXPECT_TRUE(stats.converged) << to_string(method);
    // Each row: J dv + (s / m) lambda = 0 and m dv = -m g h + 2 lambda.
    const double lambda = mass * kG * kH / (2.0 + s);
    for (const ContactState& state : owned.problem.states) EXPECT_NEAR(state.lambda, lambda, 1e-9) << to_string(method);
    EXPECT_NEAR(dv.z(), -s * lambda / mass, 1e-9) << to_string(method);
    EXPECT_LT(stats.kkt, 1e-8) << to_string(method);
  }
}

TEST(ContactSoftness, ASteadyLoadHoldsExactly) {
  const double mass = 2.0;
  for (SolverMethod method : {SolverMethod::cr, SolverMethod::pgs}) {
    OwnedProblem owned = particle_on_two_rows(0.01);
    // Warm-started with last step's split: the compliance is measured from it.
    for (ContactState& state : owned.problem.states) {
      state.mode = ContactMode::sliding;
      state.lambda = state.lambda_kinetic = 0.5 * mass * kG * kH;
    }
    Eigen::VectorXd dv;
    const ContactSolverStats stats = solve_contacts(owned.problem, solver_test::tight(method), dv);
    EXPECT_TRUE(stats.converged) << to_string(method);
    EXPECT_NEAR(dv.norm(), 0.0, 1e-10) << to_string(method);
    for (const ContactState& state : owned.problem.states)
      EXPECT_NEAR(state.lambda, 0.5 * mass * kG * kH, 1e-9) << to_string(method);
  }
}

}  // namespace
}  // namespace recoil::sim
