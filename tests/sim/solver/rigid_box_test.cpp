// Redundant rows: a rigid box on its four bottom
// corners gives 12 rows on 6 DoF, so B is singular (but consistent) and the
// split of the normal impulse among the corners is not unique. dv is: at
// rest it is zero; sliding along x it is the Coulomb deceleration mu g h,
// with no rotation (the friction torque is balanced by shifting normal
// impulse to the leading corners). The multipliers must stay finite and
// sum to the weight.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "tests/fixtures/problem_builders.h"
#include "tests/sim/solver/solver_test_support.h"

namespace recoil::sim {
namespace {

using solver_test::kG;
using solver_test::kH;
using solver_test::kMethods;
constexpr double kBoxMass = 3.0;
const Eigen::Vector3d kSize(1.0, 0.6, 0.4);
constexpr double kYaw = 0.3;  // rad: non-diagonal world inertia

struct BoxCheck {
  double dv_error = 0.0;
  double lambda_sum = 0.0;
  double lambda_max = 0.0;
};

BoxCheck check(const solver_test::Solution& s, const Eigen::Vector3d& expected_linear) {
  BoxCheck out;
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(6);
  expected.head<3>() = expected_linear;
  out.dv_error = (s.dv - expected).lpNorm<Eigen::Infinity>();
  for (const ContactState& st : s.states) {
    EXPECT_TRUE(std::isfinite(st.lambda) && std::isfinite(st.gamma.norm()));
    out.lambda_sum += st.lambda;
    out.lambda_max = std::max({out.lambda_max, std::abs(st.lambda), st.gamma.norm()});
  }
  return out;
}

TEST(SolverRigidBox, RestsOnFourCorners) {
  for (SolverMethod method : kMethods) {
    OwnedProblem owned = rigid_box_on_ground(kSize, kBoxMass, kYaw, kG, kH, Eigen::Vector3d::Zero(), 0.5, 0.5);
    const ContactSolverSettings settings = solver_test::tight(method, 1e-10, 20000);
    const auto s = solver_test::solve_copy(owned.problem, settings);
    const BoxCheck c = check(s, Eigen::Vector3d::Zero());
    std::cout << to_string(method) << ": box at rest: |dv|_inf " << c.dv_error << ", sum lambda " << c.lambda_sum
              << " (weight impulse " << kBoxMass * kG * kH << "), largest multiplier " << c.lambda_max << ", iterations "
              << s.stats.iterations << ", restarts " << s.stats.restarts << ", kkt " << s.stats.kkt << "\n";
    EXPECT_TRUE(s.stats.converged) << to_string(method);
    EXPECT_LT(c.dv_error, 1e-8) << to_string(method);
    EXPECT_NEAR(c.lambda_sum, kBoxMass * kG * kH, 1e-8) << to_string(method);
    EXPECT_LT(c.lambda_max, 2.0 * kBoxMass * kG * kH) << to_string(method);
    EXPECT_LT(s.stats.kkt, 1e-8) << to_string(method);
  }
}

TEST(SolverRigidBox, SlidesWithCoulombDeceleration) {
  const double mu = 0.4, v0 = 1.5;
  const Eigen::Vector3d velocity(v0 * std::cos(0.2), v0 * std::sin(0.2), 0.0);
  for (SolverMethod method : kMethods) {
    OwnedProblem owned = rigid_box_on_ground(kSize, kBoxMass, kYaw, kG, kH, velocity, mu, mu);
    const ContactSolverSettings settings = solver_test::tight(method, 1e-10, 20000);
    const auto s = solver_test::solve_copy(owned.problem, settings);
    const BoxCheck c = check(s, -mu * kG * kH * velocity.normalized());
    std::cout << to_string(method) << ": sliding box: |dv - (-mu g h v_hat, 0)|_inf " << c.dv_error << ", sum lambda "
              << c.lambda_sum << ", largest multiplier " << c.lambda_max << ", iterations " << s.stats.iterations
              << ", restarts " << s.stats.restarts << ", kkt " << s.stats.kkt << "\n";
    EXPECT_TRUE(s.stats.converged) << to_string(method);
    EXPECT_LT(c.dv_error, 1e-7) << to_string(method);
    EXPECT_NEAR(c.lambda_sum, kBoxMass * kG * kH, 1e-7) << to_string(method);
    EXPECT_LT(c.lambda_max, 2.0 * kBoxMass * kG * kH) << to_string(method);
    EXPECT_LT(s.stats.kkt, 1e-7) << to_string(method);
    EXPECT_EQ(s.stats.sliding, 4) << to_string(method);
  }
}

}  // namespace
}  // namespace recoil::sim
