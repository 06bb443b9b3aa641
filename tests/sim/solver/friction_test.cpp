// Friction on problems with known answers: a particle on an incline sticks
// below the friction angle and slides with g (sin - mu_k cos) above it;
// kinetic friction removes exactly mu_k g h of tangential speed per step or
// stops the particle; the cone is isotropic. Every method.
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
using solver_test::solve_copy;
using solver_test::tight;

constexpr double kMass = 2.0;

// End-of-step tangential velocity (t1, t2) of the particle.
Eigen::Vector2d tangential_velocity(const OwnedProblem& owned, const Eigen::VectorXd& dv) {
  const ContactRows& rows = owned.problem.rows[0];
  return (rows.blocks[0] * dv).tail<2>() - rows.rhs_tangent;
}

TEST(SolverFriction, ParticleSticksBelowFrictionAngle) {
  const double theta = 20.0 * M_PI / 180.0;  // tan = 0.364
  const double mu = 0.5;
  for (SolverMethod method : kMethods) {
    OwnedProblem owned = particle_on_incline(kMass, theta, kG, kH, Eigen::Vector2d::Zero(), mu, mu);
    const auto s = solve_copy(owned.problem, tight(method));
    ASSERT_TRUE(s.stats.converged) << to_string(method);
    const double creep = s.dv.norm();
    std::cout << to_string(method) << ": sticking on 20 deg, mu 0.5: |dv| = " << creep << " m/s, iterations "
              << s.stats.iterations << "\n";
    EXPECT_LT(creep, 1e-9) << to_string(method);
    EXPECT_LT(s.stats.kkt, 1e-9) << to_string(method);
    EXPECT_EQ(s.states[0].mode, ContactMode::sticking) << to_string(method);
    EXPECT_NEAR(s.states[0].lambda, kH * kMass * kG * std::cos(theta), 1e-9);
    EXPECT_NEAR(s.states[0].gamma[0], kH * kMass * kG * std::sin(theta), 1e-9);  // up the slope
  }
}

TEST(SolverFriction, ParticleSlidesWithCoulombAcceleration) {
  const double theta = 30.0 * M_PI / 180.0;  // tan = 0.577
  const double mu = 0.3;
  const double expected = kG * (std::sin(theta) - mu * std::cos(theta));  // down the slope, m/s^2
  for (SolverMethod method : kMethods) {
    OwnedProblem owned = particle_on_incline(kMass, theta, kG, kH, Eigen::Vector2d::Zero(), mu, mu);
    const auto s = solve_copy(owned.problem, tight(method));
    ASSERT_TRUE(s.stats.converged) << to_string(method);
    const Eigen::Vector2d v = tangential_velocity(owned, s.dv);
    const double acceleration = -v[0] / kH;
    const double rel = std::abs(acceleration - expected) / expected;
    std::cout << to_string(method) << ": sliding on 30 deg, mu 0.3: a = " << acceleration << " m/s^2, expected "
              << expected << ", relative error " << rel << "\n";
    EXPECT_LT(rel, 1e-6) << to_string(method);
    EXPECT_LT(s.stats.kkt, 1e-9) << to_string(method);
    EXPECT_NEAR(v[1], 0.0, 1e-9);
    EXPECT_EQ(s.states[0].mode, ContactMode::sliding) << to_string(method);
  }
}

TEST(SolverFriction, KineticFrictionRemovesMuGHPerStepOrStops) {
  const double mu = 0.5;
  for (SolverMethod method : kMethods) {
    for (double v0 : {1.0, 0.05}) {  // mu g h = 0.0818 m/s
      OwnedProblem owned = particle_on_incline(kMass, 0.0, kG, kH, Eigen::Vector2d(v0, 0.0), mu, mu);
      const auto s = solve_copy(owned.problem, tight(method));
      ASSERT_TRUE(s.stats.converged) << to_string(method);
      const Eigen::Vector2d v = tangential_velocity(owned, s.dv);
      const double expected = std::max(0.0, v0 - mu * kG * kH);
      std::cout << to_string(method) << ": v0 " << v0 << " -> " << v[0] << " m/s, expected " << expected << "\n";
      EXPECT_NEAR(v[0], expected, 1e-8) << to_string(method) << " v0 " << v0;
      EXPECT_LT(s.stats.kkt, 1e-9) << to_string(method) << " v0 " << v0;
      EXPECT_NEAR(v[1], 0.0, 1e-9);
    }
  }
}

TEST(SolverFriction, ConeIsIsotropic) {
  const double mu = 0.4;
  const double v0 = 1.0;
  for (SolverMethod method : kMethods) {
    OwnedProblem along = particle_on_incline(kMass, 0.0, kG, kH, Eigen::Vector2d(v0, 0.0), mu, mu);
    OwnedProblem diagonal =
        particle_on_incline(kMass, 0.0, kG, kH, Eigen::Vector2d(v0, v0) / std::sqrt(2.0), mu, mu);
    const auto a = solve_copy(along.problem, tight(method));
    const auto d = solve_copy(diagonal.problem, tight(method));
    ASSERT_TRUE(a.stats.converged && d.stats.converged) << to_string(method);
    // Friction impulse = m (change of tangential velocity).
    const double fa = kMass * (along.problem.rows[0].blocks[0] * a.dv).tail<2>().norm();
    const double fd = kMass * (diagonal.problem.rows[0].blocks[0] * d.dv).tail<2>().norm();
    std::cout << to_string(method) << ": friction impulse along t1 " << fa << " N s, along the diagonal " << fd
              << " N s, relative difference " << std::abs(fa - fd) / fa << "\n";
    EXPECT_NEAR(fa, mu * kMass * kG * kH, 1e-9) << to_string(method);
    EXPECT_NEAR(fd, fa, 1e-9 * fa) << to_string(method);
    const Eigen::Vector2d vd = tangential_velocity(diagonal, d.dv);
    EXPECT_NEAR(vd[0], vd[1], 1e-9) << to_string(method) << ": slides along the diagonal";
  }
}

}  // namespace
}  // namespace recoil::sim
