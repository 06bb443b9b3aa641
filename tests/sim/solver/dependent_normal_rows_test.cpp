// A rigid box resting on its four bottom corners, and a fifth contact at the
// middle of its bottom face: that row is the corners' average, so it depends
// on them. With its right-hand side asking 1 cm/s more than theirs (a bump
// under the middle), it cannot come on beside all four: one corner makes
// way, and the impulse the rows apply is unchanged by the exchange.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/geometry/skew.h"
#include "sim/solver/constraint_evaluation.h"
#include "sim/solver/contact_rows_ops.h"
#include "sim/solver/dependent_normal_rows.h"
#include "tests/fixtures/problem_builders.h"

namespace recoil::sim {
namespace {

const Eigen::Vector3d kFaceBox(1.0, 0.6, 0.4);
constexpr double kMiddleBump = 0.01;  // m/s: what the middle asks beyond the corners

// The box on its corners (contacts 0-3, rhs 0) and the middle contact (4).
OwnedProblem box_with_middle_contact() {
  OwnedProblem owned = rigid_box_on_ground(kFaceBox, 3.0, 0.3, 9.81, 0.01, Eigen::Vector3d::Zero(), 0.5, 0.5);
  ContactRows middle = owned.problem.rows[0];
  const Eigen::Matrix3d F = contact_frame(Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d r(0.0, 0.0, -0.5 * kFaceBox.z());  // under the centre of mass, whatever the yaw
  middle.blocks = {F, -F * skew(r)};
  middle.rhs_normal = kMiddleBump;
  owned.problem.rows.push_back(middle);
  owned.problem.states.emplace_back();
  return owned;
}

// J^T y's multipliers: the impulse the rows apply, per DoF.
Eigen::VectorXd rows_impulse(const ContactProblem& problem, const Eigen::VectorXd& y, int n) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(n);
  for (size_t k = 0; k < problem.rows.size(); ++k)
    add_rows_transpose_times(problem.rows[k], y.segment<3>(n + 3 * static_cast<int>(k)), out);
  return out;
}

TEST(DependentNormalRows, TheMiddleOfAFaceDependsOnItsCorners) {
  OwnedProblem owned = box_with_middle_contact();
  const MomentumPreconditioner P(*owned.problem.A);
  OnNormalRows on(owned.problem, P);
  EXPECT_FALSE(on.dependence(4).dependent) << "nothing is on yet";
  on.add(0);
  on.add(1);
  const NormalRowDependence off_edge = on.dependence(4);
  EXPECT_FALSE(off_edge.dependent) << "the middle is off the edge between corners 0 and 1";
  EXPECT_TRUE(off_edge.contacts.empty() && off_edge.coefficients.empty());
  on.add(3);
  EXPECT_TRUE(on.dependence(4).dependent) << "three corners span every normal motion of the face";
  on.add(2);
  const NormalRowDependence d = on.dependence(4);
  ASSERT_TRUE(d.dependent);
  ASSERT_EQ(d.contacts.size(), 4u);
  // The four corners depend on each other too: the smallest coefficients,
  // a quarter each, are the ones reported.
  for (double c : d.coefficients) EXPECT_NEAR(c, 0.25, 1e-9);
  EXPECT_NEAR(d.mismatch, kMiddleBump, 1e-12);
  on.remove(1);
  on.remove(2);
  const NormalRowDependence diagonal = on.dependence(4);
  ASSERT_TRUE(diagonal.dependent) << "the middle lies on the diagonal from corner 0 to corner 3";
  for (double c : diagonal.coefficients) EXPECT_NEAR(c, 0.5, 1e-9);
}

// Sliding corners too: the corner switched off must stay off when Algorithm
// 3 then updates the friction of every sliding contact that keeps its mode.
TEST(DependentNormalRows, ACornerMakesWayForADependentViolatedRow) {
  for (const ContactMode corners : {ContactMode::sticking, ContactMode::sliding}) {
    OwnedProblem owned = box_with_middle_contact();
    ContactProblem& problem = owned.problem;
    const MomentumPreconditioner P(*problem.A);
    const int n = 6, m = 5;
    Eigen::VectorXd y = Eigen::VectorXd::Zero(n + 3 * m);
    // Corners at rest, loaded unevenly; corner 1 carries the least.
    const double load[4] = {0.04, 0.01, 0.03, 0.05};
    for (int corner = 0; corner < 4; ++corner) {
      ContactState& s = problem.states[corner];
      s.mode = corners;
      s.lambda = load[corner];
      if (corners == ContactMode::sliding) {
        s.lambda_kinetic = 0.5 * load[corner];
        s.slip = Eigen::Vector2d(1.0, 0.0);
      }
      y[n + 3 * corner] = load[corner];
    }
    std::vector<Eigen::Vector3d> inverse_masses;
    for (const ContactRows& rows : problem.rows) inverse_masses.push_back(effective_inverse_mass(rows, P));
    const Eigen::VectorXd before = rows_impulse(problem, y, n);
    ContactSolverSettings settings;
    const EvaluationChanges changes = evaluate_constraints(problem, inverse_masses, y, P, settings, true);
    const char* what = corners == ContactMode::sticking ? "sticking corners" : "sliding corners";
    EXPECT_EQ(changes.mode_changes, 2) << what << ": the middle on, one corner off";
    EXPECT_NE(problem.states[4].mode, ContactMode::inactive) << what;
    EXPECT_EQ(problem.states[1].mode, ContactMode::inactive) << what << ": the smallest lambda / c leaves";
    EXPECT_EQ(y[n + 3 * 1], 0.0) << what;
    EXPECT_NEAR(y[n + 3 * 4], 4.0 * load[1], 1e-12) << what;
    for (int corner : {0, 2, 3}) {
      EXPECT_NE(problem.states[corner].mode, ContactMode::inactive) << what;
      EXPECT_NEAR(y[n + 3 * corner], load[corner] - load[1], 1e-12) << what;
    }
    EXPECT_LT((rows_impulse(problem, y, n) - before).lpNorm<Eigen::Infinity>(), 1e-12) << what;
  }
}

// Mid-solve the multipliers are not yet the system's: the middle waits
// for a converged evaluation instead of exchanging on them.
TEST(DependentNormalRows, MidSolveADependentViolatedRowWaits) {
  OwnedProblem owned = box_with_middle_contact();
  ContactProblem& problem = owned.problem;
  const MomentumPreconditioner P(*problem.A);
  const int n = 6, m = 5;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n + 3 * m);
  for (int corner = 0; corner < 4; ++corner) {
    problem.states[corner].mode = ContactMode::sticking;
    y[n + 3 * corner] = 0.01 * (corner + 1);
  }
  std::vector<Eigen::Vector3d> inverse_masses;
  for (const ContactRows& rows : problem.rows) inverse_masses.push_back(effective_inverse_mass(rows, P));
  const Eigen::VectorXd before = y;
  ContactSolverSettings settings;
  const EvaluationChanges changes = evaluate_constraints(problem, inverse_masses, y, P, settings, false);
  EXPECT_EQ(changes.total(), 0);
  EXPECT_EQ(problem.states[4].mode, ContactMode::inactive);
  EXPECT_EQ(y, before);
}

TEST(DependentNormalRows, ADependentRowTheOthersAgreeWithComesOn) {
  OwnedProblem owned = box_with_middle_contact();
  ContactProblem& problem = owned.problem;
  problem.rows[4].rhs_normal = 0.0;
  const MomentumPreconditioner P(*problem.A);
  const int n = 6, m = 5;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n + 3 * m);
  // dv sinks the box by 2 cm/s: every row is violated, the corners and the middle alike.
  y[2] = -0.02;
  std::vector<Eigen::Vector3d> inverse_masses;
  for (const ContactRows& rows : problem.rows) inverse_masses.push_back(effective_inverse_mass(rows, P));
  ContactSolverSettings settings;
  const EvaluationChanges changes = evaluate_constraints(problem, inverse_masses, y, P, settings, true);
  EXPECT_EQ(changes.mode_changes, 5) << "a flat face's rows agree: all come on";
  for (const ContactState& s : problem.states) EXPECT_NE(s.mode, ContactMode::inactive);
}

}  // namespace
}  // namespace recoil::sim
