// Which penetrating contacts EvaluateConstraints switches on together: of
// nearly parallel normal rows only the deepest, the rest after a solve
// (constraint_evaluation.h); rows at an angle all at once.
#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "sim/solver/constraint_evaluation.h"
#include "sim/solver/contact_rows_ops.h"
#include "tests/fixtures/problem_builders.h"

namespace recoil::sim {
namespace {

constexpr double kEps2 = 1e-6;  // m/s

// One free point mass (A = m I, so the P_A^-1 metric is the plain one) with
// three inactive contacts on it: normals (0, 0, 1), `second` and (1, 0, 0),
// penetrating by 0.020, 0.019 and 0.0195 m/s at dv = 0.
struct PointWithThreeContacts {
  OwnedProblem owned;
  std::vector<Eigen::Vector3d> inverse_masses;
  std::optional<MomentumPreconditioner> P;
  Eigen::VectorXd y;

  explicit PointWithThreeContacts(const Eigen::Vector3d& second) {
    owned.A = mass_spring_matrix({2.0}, {}, 0.0);
    owned.problem.A = owned.A.get();
    owned.problem.b = Eigen::Vector3d::Zero();
    add_contact(owned.problem, {0}, {1.0}, Eigen::Vector3d(0.0, 0.0, 1.0), 0.020, 0.5, 0.5);
    add_contact(owned.problem, {0}, {1.0}, second.normalized(), 0.019, 0.5, 0.5);
    add_contact(owned.problem, {0}, {1.0}, Eigen::Vector3d(1.0, 0.0, 0.0), 0.0195, 0.5, 0.5);
    P.emplace(*owned.A);
    for (size_t k = 0; k < 3; ++k) inverse_masses.push_back(effective_inverse_mass(owned.problem.rows[k], *P));
    y = Eigen::VectorXd::Zero(3 + 3 * 3);
  }
  bool active(int k) const { return owned.problem.states[static_cast<size_t>(k)].mode != ContactMode::inactive; }
  int evaluate(bool converged, const ContactPolicy& policy = {}) {
    ContactSolverSettings settings;
    settings.constraint_tolerance = kEps2;
    settings.policy = policy;
    return evaluate_constraints(owned.problem, inverse_masses, y, *P, settings, converged).total();
  }
};

TEST(ActivationOrder, OfTwoNearlyParallelRowsOnlyTheDeeperComesOn) {
  PointWithThreeContacts p(Eigen::Vector3d(0.0, 0.05, 1.0));  // cosine 0.9988 with the first
  EXPECT_EQ(p.evaluate(true), 2);
  EXPECT_TRUE(p.active(0));
  EXPECT_FALSE(p.active(1));  // waits for the solve
  EXPECT_TRUE(p.active(2));   // at right angles to both: on at once
  // Mid-solve, a row parallel to an active one keeps waiting ...
  EXPECT_EQ(p.evaluate(false), 0);
  EXPECT_FALSE(p.active(1));
  // ... and comes on at a solved evaluation if it still penetrates. The two
  // contacts already on, at rest, do not stick with it: at dv = 0 either
  // one's sticking rows would hold the point against the other's normal row.
  EXPECT_EQ(p.evaluate(true), 1);
  EXPECT_TRUE(p.active(1));
  for (int k = 0; k < 3; ++k) EXPECT_EQ(p.owned.problem.states[static_cast<size_t>(k)].mode, ContactMode::sliding) << k;
}

TEST(ActivationOrder, ThePolicySetsTheParallelThreshold) {
  // The same rows with the parallel cosine raised past 0.9988: all three on.
  ContactPolicy loose;
  loose.parallel = 0.9995;
  PointWithThreeContacts p(Eigen::Vector3d(0.0, 0.05, 1.0));
  EXPECT_EQ(p.evaluate(true, loose), 3);
}

TEST(ActivationOrder, RowsAtAnAngleComeOnTogether) {
  PointWithThreeContacts p(Eigen::Vector3d(0.0, 1.0, 1.0));  // cosine 0.71 with the first
  EXPECT_EQ(p.evaluate(true), 3);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(p.active(k)) << k;
}

}  // namespace
}  // namespace recoil::sim
