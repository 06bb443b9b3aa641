// Anderson acceleration of Algorithm 3's fixed point (friction_acceleration.h):
// it reaches a strongly coupled linear fixed point in a few steps where the
// damped plain iteration crawls or diverges, forgets its pairs when the
// members change or an extrapolated step grew the residual, and measures
// slip angles across the +-pi seam.
#include "sim/solver/friction_acceleration.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <numbers>

namespace recoil::sim {
namespace {

// Steps until |x - x*| < 1e-10 under G(x) = A x + b, with `accelerated` or the
// damped plain step x + mixing (G(x) - x); at most `cap`.
int steps_to_fixed_point(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, bool accelerated, int cap) {
  const Eigen::VectorXd solution = (Eigen::MatrixXd::Identity(A.rows(), A.cols()) - A).lu().solve(b);
  const std::vector<int> members = {3, 8};
  const Eigen::VectorXd weights = Eigen::VectorXd::Ones(4);
  FrictionAcceleration acceleration;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
  for (int step = 0; step < cap; ++step) {
    if ((x - solution).norm() < 1e-10) return step;
    const Eigen::VectorXd g = A * x + b;
    x = accelerated ? acceleration.next(members, x, g, weights, 0.5) : Eigen::VectorXd(x + 0.5 * (g - x));
  }
  return cap;
}

TEST(FrictionAcceleration, ReachesACoupledLinearFixedPointInAFewSteps) {
  // Two contacts' (lambda', angle) pairs coupled strongly: G's Jacobian has
  // eigenvalues near 1 (the plain step crawls) and near -1 (a whole step swings).
  Eigen::MatrixXd A(4, 4);
  A << 0.97, 0.01, 0.00, 0.00,  //
      0.00, -0.90, 0.05, 0.00,  //
      0.02, 0.00, 0.60, 0.30,   //
      0.00, 0.01, 0.30, 0.65;
  const Eigen::VectorXd b = Eigen::Vector4d(0.1, 0.2, -0.05, 0.3);
  const int plain = steps_to_fixed_point(A, b, false, 2000);
  const int accelerated = steps_to_fixed_point(A, b, true, 2000);
  EXPECT_GT(plain, 300);
  EXPECT_LE(accelerated, 15);
}

TEST(FrictionAcceleration, ReachesAFixedPointWhereTheDampedStepDiverges) {
  // A slope of -3.5 (a loaded jelly cube's bottom face: more friction at a
  // contact takes load off it) makes the half step x + (G(x) - x) / 2 grow
  // the residual 1.25 times a step; the residual grows on every such step,
  // and a history forgotten when it grew never leaves the plain step.
  Eigen::MatrixXd A(4, 4);
  A << -3.5, 0.20, 0.00, 0.00,  //
      0.10, 0.50, 0.00, 0.00,   //
      0.00, 0.00, 0.30, 0.10,   //
      0.00, 0.00, 0.00, 0.80;
  const Eigen::VectorXd b = Eigen::Vector4d(1.0, 0.02, -0.01, 0.01);
  EXPECT_EQ(steps_to_fixed_point(A, b, false, 200), 200);
  EXPECT_LE(steps_to_fixed_point(A, b, true, 200), 15);
}

TEST(FrictionAcceleration, AResidualGrownAfterAnExtrapolatedStepStartsAfresh) {
  FrictionAcceleration acceleration;
  const Eigen::VectorXd weights = Eigen::VectorXd::Ones(2);
  // Two pairs with a shrinking residual: the second step is extrapolated.
  acceleration.next({4}, Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(1.0, 0.1), weights, 0.5);
  acceleration.next({4}, Eigen::Vector2d(0.5, 0.05), Eigen::Vector2d(1.2, 0.1), weights, 0.5);
  // Its residual grew: the pairs are dropped and the step is the damped plain one.
  const Eigen::Vector2d x(3.0, 0.0), g(5.0, 0.2);
  const Eigen::VectorXd next = acceleration.next({4}, x, g, weights, 0.5);
  EXPECT_NEAR(next[0], 4.0, 1e-15);
  EXPECT_NEAR(next[1], 0.1, 1e-15);
}

TEST(FrictionAcceleration, OtherMembersStartAfresh) {
  FrictionAcceleration acceleration;
  const Eigen::VectorXd weights = Eigen::VectorXd::Ones(2);
  Eigen::VectorXd x = Eigen::Vector2d(1.0, 0.2);
  for (int step = 0; step < 3; ++step) x = acceleration.next({5}, x, Eigen::Vector2d(0.5 * x[0] + 1.0, 0.1), weights, 0.5);
  // Another contact, its residual smaller than contact 5's last (so only the
  // change of members can drop the pairs): the step is the damped plain one.
  const Eigen::Vector2d y(2.0, 0.0), g(2.02, 0.004);
  const Eigen::VectorXd next = acceleration.next({6}, y, g, weights, 0.5);
  EXPECT_NEAR(next[0], 2.01, 1e-15);
  EXPECT_NEAR(next[1], 0.002, 1e-15);
}

TEST(FrictionAcceleration, AnglesAcrossThePiSeamTurnTheShortWay) {
  FrictionAcceleration acceleration;
  const double pi = std::numbers::pi;
  // From just below +pi to just above -pi is 0.02 rad counter-clockwise, not 2 pi - 0.02 back.
  const Eigen::VectorXd next = acceleration.next({0}, Eigen::Vector2d(1.0, pi - 0.01), Eigen::Vector2d(1.0, -pi + 0.01),
                                                 Eigen::Vector2d(1.0, 1.0), 0.5);
  EXPECT_NEAR(next[1], pi, 1e-12);
}

}  // namespace
}  // namespace recoil::sim
