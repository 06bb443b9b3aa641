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
#include "sim/solver/dependent_rows.h"
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

// Contact k's normal row, against the rows on after an evaluation: either
// independent of them or agreeing with them, so that the equalities the
// next solve starts from have a solution.
void expect_consistent(const ContactProblem& problem, const MomentumPreconditioner& P, int k, const char* what) {
  OnRows on(problem, P);
  for (size_t t = 0; t < problem.states.size(); ++t)
    if (problem.states[t].mode != ContactMode::inactive)
      on.add(static_cast<int>(t), problem.states[t].mode == ContactMode::sticking);
  const RowDependence d = on.dependence(k);
  EXPECT_TRUE(!d.dependent || std::abs(d.mismatch) <= ContactSolverSettings{}.constraint_tolerance)
      << what << ": mismatch " << d.mismatch;
}

// J^T y's multipliers: the impulse the rows apply, per DoF.
Eigen::VectorXd rows_impulse(const ContactProblem& problem, const Eigen::VectorXd& y, int n) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(n);
  for (size_t k = 0; k < problem.rows.size(); ++k)
    add_rows_transpose_times(problem.rows[k], y.segment<3>(n + 3 * static_cast<int>(k)), out);
  return out;
}

TEST(DependentRows, TheMiddleOfAFaceDependsOnItsCorners) {
  OwnedProblem owned = box_with_middle_contact();
  const MomentumPreconditioner P(*owned.problem.A);
  OnRows on(owned.problem, P);
  EXPECT_FALSE(on.dependence(4).dependent) << "nothing is on yet";
  on.add(0, false);
  on.add(1, false);
  const RowDependence off_edge = on.dependence(4);
  EXPECT_FALSE(off_edge.dependent) << "the middle is off the edge between corners 0 and 1";
  EXPECT_TRUE(off_edge.contacts.empty() && off_edge.coefficients.empty());
  on.add(3, false);
  EXPECT_TRUE(on.dependence(4).dependent) << "three corners span every normal motion of the face";
  on.add(2, false);
  const RowDependence d = on.dependence(4);
  ASSERT_TRUE(d.dependent);
  ASSERT_EQ(d.contacts.size(), 4u);
  // The four corners depend on each other too: the smallest coefficients,
  // a quarter each, are the ones reported.
  for (const Eigen::Vector3d& c : d.coefficients) {
    EXPECT_NEAR(c[0], 0.25, 1e-9);
    EXPECT_EQ(c.tail<2>(), Eigen::Vector2d::Zero()) << "the corners' tangent rows are not on";
  }
  EXPECT_NEAR(d.mismatch, kMiddleBump, 1e-12);
  on.remove(1);
  on.remove(2);
  const RowDependence diagonal = on.dependence(4);
  ASSERT_TRUE(diagonal.dependent) << "the middle lies on the diagonal from corner 0 to corner 3";
  for (const Eigen::Vector3d& c : diagonal.coefficients) EXPECT_NEAR(c[0], 0.5, 1e-9);
}

// Sliding corners too: the corner switched off must stay off when Algorithm
// 3 then updates the friction of every sliding contact that keeps its mode.
TEST(DependentRows, ACornerMakesWayForADependentViolatedRow) {
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
    // Corner 1 (smallest lambda / c, c = 1/4 each) leaves first; the middle
    // still lies on the diagonal from corner 0 to corner 3, and of those two
    // (c = 1/2 each) corner 0 leaves next.
    EXPECT_EQ(changes.mode_changes, 3) << what << ": the middle on, two corners off";
    EXPECT_NE(problem.states[4].mode, ContactMode::inactive) << what;
    for (int corner : {0, 1}) {
      EXPECT_EQ(problem.states[corner].mode, ContactMode::inactive) << what;
      EXPECT_EQ(y[n + 3 * corner], 0.0) << what;
    }
    const double first = load[1], second = 2.0 * (load[0] - first);  // lambda of the middle from each exchange
    EXPECT_NEAR(y[n + 3 * 4], 4.0 * first + second, 1e-12) << what;
    EXPECT_NEAR(y[n + 3 * 2], load[2] - first, 1e-12) << what;
    EXPECT_NEAR(y[n + 3 * 3], load[3] - first - 0.5 * second, 1e-12) << what;
    for (int corner : {2, 3}) EXPECT_NE(problem.states[corner].mode, ContactMode::inactive) << what;
    EXPECT_LT((rows_impulse(problem, y, n) - before).lpNorm<Eigen::Infinity>(), 1e-12) << what;
    expect_consistent(problem, P, 4, what);
  }
}

// Mid-solve the multipliers are not yet the system's: the middle waits
// for a converged evaluation instead of exchanging on them.
TEST(DependentRows, MidSolveADependentViolatedRowWaits) {
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

// The impulse the contacts apply, per DoF, as their states and y say
// (a sliding contact's friction is in its state, not in y).
Eigen::VectorXd contact_impulse(const ContactProblem& problem, const Eigen::VectorXd& y, int n) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(n);
  for (size_t k = 0; k < problem.rows.size(); ++k) {
    const ContactState& s = problem.states[k];
    Eigen::Vector3d f = y.segment<3>(n + 3 * static_cast<int>(k));
    if (s.mode == ContactMode::sliding) f.tail<2>() = tangent_impulse(problem.rows[k], s);
    add_rows_transpose_times(problem.rows[k], f, out);
  }
  return out;
}

// Four sticking corners hold every motion of the box, so a wall contact on
// its side depends on their tangent rows, though on no normal row. The
// wall closing in at 1 cm/s cannot come on beside them: the corner whose
// friction first reaches its static cone's rim along the exchange slides.
TEST(DependentRows, AStickingCornerSlidesForAWallItsFrictionWouldHoldOff) {
  OwnedProblem owned = rigid_box_on_ground(kFaceBox, 3.0, 0.3, 9.81, 0.01, Eigen::Vector3d::Zero(), 0.5, 0.5);
  ContactProblem& problem = owned.problem;
  ContactRows wall = problem.rows[0];
  const Eigen::Matrix3d F = contact_frame(Eigen::Vector3d::UnitX());
  const Eigen::Vector3d r(-0.5 * kFaceBox.x(), 0.05, 0.0);  // on the -x face, off the centre line
  wall.blocks = {F, -F * skew(r)};
  wall.rhs_normal = 0.01;
  problem.rows.push_back(wall);
  problem.states.emplace_back();
  const MomentumPreconditioner P(*problem.A);
  const int n = 6, m = 5;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n + 3 * m);
  const double load[4] = {0.04, 0.01, 0.03, 0.05};
  for (int corner = 0; corner < 4; ++corner) {
    problem.states[corner].mode = ContactMode::sticking;
    y[n + 3 * corner] = load[corner];
  }
  std::vector<Eigen::Vector3d> inverse_masses;
  for (const ContactRows& rows : problem.rows) inverse_masses.push_back(effective_inverse_mass(rows, P));
  const Eigen::VectorXd before = contact_impulse(problem, y, n);
  OnRows normals_only(problem, P);
  for (int corner = 0; corner < 4; ++corner) normals_only.add(corner, false);
  EXPECT_FALSE(normals_only.dependence(4).dependent) << "no normal row of the corners reaches sideways";
  ContactSolverSettings settings;
  const EvaluationChanges changes = evaluate_constraints(problem, inverse_masses, y, P, settings, true);
  // Sticking corners fix the box until only one is left: corners slide, one
  // exchange at a time, the first to reach its cone's rim first, until the
  // wall's row no longer depends on them.
  EXPECT_EQ(problem.states[4].mode, ContactMode::sliding);
  EXPECT_GT(y[n + 3 * 4], 0.0);
  int sliding = 0;
  for (int corner = 0; corner < 4; ++corner) {
    const ContactState& s = problem.states[corner];
    const Eigen::Vector3d f = y.segment<3>(n + 3 * corner);
    ASSERT_NE(s.mode, ContactMode::inactive);
    EXPECT_GE(f[0], 0.0);
    if (s.mode == ContactMode::sliding) {
      ++sliding;
    } else {
      EXPECT_LE(f.tail<2>().norm(), 0.5 * f[0] + 1e-12) << "inside the cone";
    }
  }
  EXPECT_GE(sliding, 1);
  EXPECT_EQ(changes.mode_changes, 1 + sliding) << "the wall on, the corners that slide";
  EXPECT_LT((contact_impulse(problem, y, n) - before).lpNorm<Eigen::Infinity>(), 1e-12);
  expect_consistent(problem, P, 4, "the wall");
}

// Three sticking corners hold the box still, so the fourth corner's slip is
// theirs to decide: with the ground under it moving at 1 cm/s, its slip
// cannot stop. Sliding against that motion, it reads as reversed, but it
// keeps sliding instead of sticking on rows that contradict the others.
TEST(DependentRows, ASlidingCornerTheOthersHoldStillKeepsSliding) {
  OwnedProblem owned = rigid_box_on_ground(kFaceBox, 3.0, 0.3, 9.81, 0.01, Eigen::Vector3d::Zero(), 0.5, 0.5);
  ContactProblem& problem = owned.problem;
  problem.rows[3].rhs_tangent = Eigen::Vector2d(0.01, 0.0);
  const MomentumPreconditioner P(*problem.A);
  const int n = 6, m = 4;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n + 3 * m);
  for (int corner = 0; corner < 4; ++corner) {
    problem.states[corner].mode = ContactMode::sticking;
    y[n + 3 * corner] = 0.03;
  }
  ContactState& fourth = problem.states[3];
  fourth.mode = ContactMode::sliding;
  fourth.lambda_kinetic = 0.03;
  fourth.slip = Eigen::Vector2d(1.0, 0.0);  // u = -rhs_tangent at dv = 0 runs against it
  std::vector<Eigen::Vector3d> inverse_masses;
  for (const ContactRows& rows : problem.rows) inverse_masses.push_back(effective_inverse_mass(rows, P));
  ContactSolverSettings settings;
  const EvaluationChanges changes = evaluate_constraints(problem, inverse_masses, y, P, settings, true);
  EXPECT_EQ(changes.mode_changes, 0);
  EXPECT_EQ(problem.states[3].mode, ContactMode::sliding);
  for (int corner = 0; corner < 3; ++corner) EXPECT_EQ(problem.states[corner].mode, ContactMode::sticking);
}

TEST(DependentRows, ADependentRowTheOthersAgreeWithComesOn) {
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
